using System;
using System.Collections.Generic;

namespace Rendering;

public partial class PropertyAnimator
{
  /// <summary>
  /// One named animated quantity: a list of Catmull–Rom knots spaced evenly in time.
  /// Read-only once set up, so clones of the animator share it.
  /// </summary>
  /// <remarks>
  /// Open data (<see cref="cyclic"/> false): <c>data[0]</c> and <c>data[N-1]</c> only shape the
  /// ends; the curve runs through <c>data[1]</c> … <c>data[N-2]</c>, so N knots give N − 3
  /// segments. Closed data (<see cref="cyclic"/> true): <c>data[N-1]</c> is followed by
  /// <c>data[0]</c>, so N knots give N segments and the curve ends where it started.
  /// </remarks>
  /// <typeparam name="T">double, float, Vector3(d), Vector4(d), Quaterniond, Matrix4d, or arrays of the vector types.</typeparam>
  [Serializable]
  public class Property<T>
  {
    /// <summary>Unique name the scene's objects ask for.</summary>
    public string name = "";

    /// <summary>The knots.</summary>
    public List<T>? data;

    /// <summary>Closed curve: the last knot is followed by the first.</summary>
    public bool cyclic;

    /// <summary>Time when the curve starts.</summary>
    public double tStart;

    /// <summary>Time when the curve ends (for <see cref="InterpolationStyle.Once"/>) or stops repeating.</summary>
    public double tEnd;

    /// <summary>Duration of one pass for <see cref="InterpolationStyle.Cyclic"/> and <see cref="InterpolationStyle.Pendulum"/>.</summary>
    public double tPeriod;

    /// <summary>How the curve is played over time (once, repeated, back and forth).</summary>
    public InterpolationStyle style;

    /// <summary>Seconds between neighbouring knots on the curve.</summary>
    public virtual double interval()
    {
      int n = Math.Max(intervals(), 1);
      return (style == InterpolationStyle.Once ? tEnd - tStart : tPeriod) / n;
    }

    /// <summary>Number of knot-to-knot segments of the curve.</summary>
    public virtual int intervals()
    {
      int len = data?.Count ?? 0;
      if (len == 0)
        return 0;
      if (cyclic)
        return len == 1 ? 0 : len;
      return Math.Max(len - 3, 0);
    }

    /// <summary>
    /// Position on the curve at time <paramref name="t"/> as 0 (curve start) … 1 (curve end),
    /// after applying <see cref="style"/>.
    /// </summary>
    public virtual double CurveParameter(double t)
    {
      if (!(t > tStart))
        return 0.0;
      if (style == InterpolationStyle.Once)
        return tEnd > tStart ? Math.Min((t - tStart) / (tEnd - tStart), 1.0) : 1.0;

      if (!(tPeriod > 0.0))
        return 0.0;
      double u = (Math.Min(t, tEnd) - tStart) / tPeriod;
      double passes = Math.Floor(u);
      double s = u - passes;
      if (style == InterpolationStyle.Pendulum && ((long)passes & 1L) == 1L)
        s = 1.0 - s;
      return s;
    }

    /// <summary>
    /// The four knots and the fraction between the middle two for time <paramref name="t"/>.
    /// Returns false when there is no data. With too few knots for a curve, all four indices
    /// point at one knot and the value is constant.
    /// </summary>
    public virtual bool prepareCubic(double t, out double fraction, out int i0, out int i1, out int i2, out int i3)
    {
      int len = data?.Count ?? 0;
      int segments = intervals();
      fraction = 0.0;
      if (segments == 0)
      {
        i0 = i1 = i2 = i3 = len == 0 ? -1 : (len - 1) / 2;
        return len > 0;
      }

      double x = CurveParameter(t) * segments;
      int seg = (int)Math.Floor(x);
      fraction = x - seg;
      // A time that should sit exactly on a knot may land a rounding error short of it.
      if (fraction > 1.0 - 1.0e-12)
      {
        seg++;
        fraction = 0.0;
      }
      if (seg >= segments)
      {
        seg = segments - 1;
        fraction = 1.0;
      }

      if (cyclic)
      {
        i1 = seg;
        i0 = (seg + len - 1) % len;
        i2 = (seg + 1) % len;
        i3 = (seg + 2) % len;
      }
      else
      {
        i0 = seg;
        i1 = seg + 1;
        i2 = seg + 2;
        i3 = seg + 3;
      }
      return true;
    }
  }
}
