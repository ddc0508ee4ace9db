using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Style = Rendering.PropertyAnimator.InterpolationStyle;

namespace GrCis.Rendering.Tests.Animation;

public class PropertyAnimatorTests
{
  static PropertyAnimator With<T>(string name, Style style, List<T> data, bool cyclic, double start = 0.0, double end = 10.0, double period = 10.0)
  {
    var a = new PropertyAnimator { Start = -100.0, End = 100.0 };
    a.newProperty(name, start, end, period, style, data, cyclic);
    return a;
  }

  static double At(PropertyAnimator a, string name, double t)
  {
    a.Time = t;
    double v = double.NaN;
    Assert.True(a.TryGetValue(name, ref v));
    return v;
  }

  [Fact]
  public void Open_curve_passes_through_the_inner_knots_at_even_times()
  {
    // 6 knots, outer ones shape the ends: segments 1→2→3→4 over [0, 9], knots every 3 s.
    var a = With("x", Style.Once, new List<double> { 7, 1, 4, -2, 8, 3 }, false, 0.0, 9.0);
    Assert.Equal(1.0, At(a, "x", 0.0));
    Assert.Equal(4.0, At(a, "x", 3.0), 12);
    Assert.Equal(-2.0, At(a, "x", 6.0), 12);
    Assert.Equal(8.0, At(a, "x", 9.0));
  }

  [Fact]
  public void Midpoint_uses_the_catmull_rom_weights()
  {
    var a = With("x", Style.Once, new List<double> { 2, 4, 8, 16 }, false);
    // (-1·2 + 9·4 + 9·8 − 1·16) / 16
    Assert.Equal((-2.0 + 36.0 + 72.0 - 16.0) / 16.0, At(a, "x", 5.0), 12);
  }

  [Fact]
  public void Once_holds_the_first_and_last_values_outside_its_interval()
  {
    var a = With("x", Style.Once, new List<double> { 0, 1, 2, 3 }, false, 2.0, 4.0);
    Assert.Equal(1.0, At(a, "x", -50.0));
    Assert.Equal(2.0, At(a, "x", 50.0));
  }

  [Fact]
  public void Cyclic_style_repeats_every_period_and_closed_data_wraps_to_the_first_knot()
  {
    // Closed curve of 4 knots over a 4 s period: knot k at t = k, back to knot 0 at t = 4.
    var a = With("x", Style.Cyclic, new List<double> { 5, 1, 7, 3 }, true, 0.0, 100.0, 4.0);
    Assert.Equal(5.0, At(a, "x", 0.0));
    Assert.Equal(7.0, At(a, "x", 2.0), 12);
    Assert.Equal(3.0, At(a, "x", 3.0), 12);
    Assert.Equal(5.0, At(a, "x", 4.0), 12);
    Assert.Equal(At(a, "x", 1.3), At(a, "x", 9.3), 12);
    // The wrap segment 3 → 0 uses knots 2, 3, 0, 1.
    Assert.Equal(CatmullRom.Interpolate(7.0, 3.0, 5.0, 1.0, 0.5), At(a, "x", 3.5), 12);
  }

  [Fact]
  public void Pendulum_plays_forwards_then_backwards()
  {
    var a = With("x", Style.Pendulum, new List<double> { 0, 1, 5, 2, 9 }, false, 0.0, 100.0, 2.0);
    Assert.Equal(1.0, At(a, "x", 0.0));
    Assert.Equal(2.0, At(a, "x", 2.0), 12);
    Assert.Equal(1.0, At(a, "x", 4.0), 12);
    for (double d = 0.1; d < 2.0; d += 0.37)
      Assert.Equal(At(a, "x", 2.0 - d), At(a, "x", 2.0 + d), 12);
    Assert.Equal(At(a, "x", 0.7), At(a, "x", 4.7), 12);
  }

  [Fact]
  public void Vectors_interpolate_per_component_and_floats_read_double_data()
  {
    var data = new List<Vector3d> { new(0, 0, 0), new(1, 2, 3), new(2, 4, 6), new(3, 6, 9) };
    var a = With("p", Style.Once, data, false);
    a.Time = 2.5;
    Vector3d v = default;
    Assert.True(a.TryGetValue("p", ref v));
    Assert.Equal(1.25, v.X, 12);
    Assert.Equal(3.75, v.Z, 12);
    Vector3 f = default;
    Assert.True(a.TryGetValue("p", ref f));
    Assert.Equal(2.5f, f.Y, 5);

    var a4 = With("q", Style.Once, new List<Vector4d> { Vector4d.Zero, Vector4d.One, 2 * Vector4d.One, 3 * Vector4d.One }, false);
    a4.Time = 5.0;
    Vector4d w = default;
    Assert.True(a4.TryGetValue("q", ref w));
    Assert.Equal(1.5, w.W, 12);
  }

  [Fact]
  public void Unknown_names_and_wrong_types_leave_the_value_and_ask_the_chain()
  {
    var next = With("other", Style.Once, new List<double> { 0, 42, 42, 0 }, false);
    var a = new PropertyAnimator(null, next);
    a.newProperty("x", 0.0, 10.0, 10.0, Style.Once, new List<double> { 0, 1, 2, 3 });
    a.Time = 0.0;

    Vector3d v = new(9, 9, 9);
    Assert.False(a.TryGetValue("x", ref v));
    Assert.Equal(new Vector3d(9, 9, 9), v);
    double d = -1.0;
    Assert.False(a.TryGetValue("missing", ref d));
    Assert.Equal(-1.0, d);
    Assert.True(a.TryGetValue("other", ref d));
    Assert.Equal(42.0, d);
    Assert.Equal(42.0, (double)a.GetValue("other")!);
  }

  [Fact]
  public void Quaternions_stay_unit_and_hit_their_knots()
  {
    var knots = new List<Quaterniond>
    {
      Quaterniond.FromAxisAngle(Vector3d.UnitY, 0.0),
      Quaterniond.FromAxisAngle(Vector3d.UnitX, 0.8),
      // Same rotation as a positive angle about −z but stored in the opposite hemisphere.
      -1.0 * Quaterniond.FromAxisAngle(Vector3d.UnitZ, 1.5),
      Quaterniond.FromAxisAngle(new Vector3d(1, 1, 0).Normalized(), 2.5),
      Quaterniond.FromAxisAngle(Vector3d.UnitY, 3.0),
    };
    var a = With("r", Style.Once, knots, false, 0.0, 2.0);
    Quaterniond q = default;

    for (double t = 0.0; t <= 2.0; t += 0.05)
    {
      a.Time = t;
      Assert.True(a.TryGetValue("r", ref q));
      Assert.Equal(1.0, q.Length, 12);
    }

    a.Time = 0.0;
    a.TryGetValue("r", ref q);
    Assert.Equal(1.0, System.Math.Abs(Quaterniond.Dot(q, knots[1])), 12);
    a.Time = 1.0;
    a.TryGetValue("r", ref q);
    Assert.Equal(1.0, System.Math.Abs(Quaterniond.Dot(q, knots[2])), 12);
    a.Time = 2.0;
    a.TryGetValue("r", ref q);
    Assert.Equal(1.0, System.Math.Abs(Quaterniond.Dot(q, knots[3])), 12);
  }

  [Fact]
  public void Quaternion_spline_through_rotations_about_one_axis_interpolates_the_angle()
  {
    // Rotations about one axis are a great circle; the spherical spline is then the
    // Catmull–Rom spline of the angle.
    double[] angles = { 0.1, 0.4, 1.2, 1.5 };
    var knots = new List<Quaterniond>();
    foreach (double ang in angles)
      knots.Add(Quaterniond.FromAxisAngle(Vector3d.UnitZ, ang));
    var a = With("r", Style.Once, knots, false, 0.0, 1.0);
    a.Time = 0.3;
    Quaterniond q = default;
    Assert.True(a.TryGetValue("r", ref q));
    q.ToAxisAngle(out Vector3d axis, out double angle);
    Assert.Equal(CatmullRom.Interpolate(angles[0], angles[1], angles[2], angles[3], 0.3), angle, 9);
    Assert.Equal(1.0, axis.Z, 9);
  }

  [Fact]
  public void Array_properties_interpolate_element_wise()
  {
    var a = With("ps", Style.Once, new List<Vector3d[]>
    {
      new[] { Vector3d.Zero, Vector3d.Zero },
      new[] { Vector3d.UnitX, Vector3d.UnitY },
      new[] { 2 * Vector3d.UnitX, 2 * Vector3d.UnitY },
      new[] { 3 * Vector3d.UnitX, 3 * Vector3d.UnitY },
    }, false);
    a.Time = 5.0;
    var v = (Vector3d[])a.GetValue("ps")!;
    Assert.Equal(1.5, v[0].X, 12);
    Assert.Equal(1.5, v[1].Y, 12);
  }

  [Fact]
  public void Clone_shares_the_data_but_has_its_own_time()
  {
    var a = With("x", Style.Once, new List<double> { 0, 0, 10, 10 }, false);
    a.Time = 0.0;
    var b = (PropertyAnimator)a.Clone();
    b.Time = 10.0;
    Assert.Equal(0.0, At(a, "x", a.Time));
    Assert.Equal(10.0, At(b, "x", b.Time));
    Assert.Equal(a.PropertyNames, b.PropertyNames);
  }

  [Fact]
  public void Time_is_clamped_to_the_animator_range()
  {
    var a = new PropertyAnimator { Start = 1.0, End = 2.0 };
    a.Time = 5.0;
    Assert.Equal(2.0, a.Time);
  }
}
