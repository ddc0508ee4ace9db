using System;
using System.Runtime.Intrinsics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The mesh walks' per-ray set-up is branch-free and vectorized; it must give the same values, to the bit, as the plain
/// scalar definitions it replaced: outward rounding to floats (<see cref="MeshNode.Down(double)"/>, <see cref="MeshNode.Up(double)"/>
/// and their four-lane forms) and the line's interval in the mesh's box (<see cref="MeshBvh.LineBox"/>).
/// </summary>
public class MeshSetupTests
{
  // The definitions: the nearest float, stepped once toward the bound when it lies on the wrong side.
  static float DownReference(double x)
  {
    float f = (float)x;
    return f > x ? MathF.BitDecrement(f) : f;
  }

  static float UpReference(double x)
  {
    float f = (float)x;
    return f < x ? MathF.BitIncrement(f) : f;
  }

  static readonly double[] Special =
  {
    0.0, -0.0, double.Epsilon, -double.Epsilon, 1e-46, -1e-46, 7e-46, -7e-46, 1.4e-45, -1.4e-45, float.Epsilon, -float.Epsilon,
    float.MaxValue, -float.MaxValue, 3.4028235677973366e38, -3.4028235677973366e38, 3.5e38, -3.5e38, 1e300, -1e300,
    double.MaxValue, double.MinValue, double.PositiveInfinity, double.NegativeInfinity, double.NaN, 1.0, -1.0,
    1.0 + 1e-16, 1.0 - 1e-17, 0.1, -0.1, 1.1754942e-38, -1.1754942e-38, 1.1754943508222875e-38,
  };

  // Values of every magnitude, float-exact ones, and values a hair beside a float.
  static double Sample(Random r)
  {
    switch (r.Next(4))
    {
      case 0:
        return Special[r.Next(Special.Length)];
      case 1:
        return (double)BitConverter.Int32BitsToSingle(r.Next()) * (r.Next(2) == 0 ? 1 : -1);
      case 2:
      {
        double f = BitConverter.Int32BitsToSingle(r.Next());
        return f + f * (r.NextDouble() - 0.5) * 1e-9;
      }
      default:
        return (r.NextDouble() - 0.5) * Math.Pow(2, r.Next(-160, 140));
    }
  }

  static bool Same(float a, float b) => BitConverter.SingleToInt32Bits(a) == BitConverter.SingleToInt32Bits(b);

  [Fact]
  public void Outward_rounding_gives_the_bits_of_its_definition_in_scalar_and_four_lane_form()
  {
    var r = new Random(2027);
    for (int i = 0; i < 200_000; i++)
    {
      double a = Sample(r), b = Sample(r), c = Sample(r), d = Sample(r);
      Assert.True(Same(MeshNode.Down(a), DownReference(a)), $"Down({a:R}) = {MeshNode.Down(a):R}, not {DownReference(a):R}");
      Assert.True(Same(MeshNode.Up(a), UpReference(a)), $"Up({a:R}) = {MeshNode.Up(a):R}, not {UpReference(a):R}");
      Vector128<float> down = MeshNode.Down(Vector256.Create(a, b, c, d)), up = MeshNode.Up(Vector256.Create(a, b, c, d));
      double[] x = { a, b, c, d };
      for (int lane = 0; lane < 4; lane++)
      {
        Assert.True(Same(down.GetElement(lane), DownReference(x[lane])), $"four-lane Down({x[lane]:R}) = {down.GetElement(lane):R}");
        Assert.True(Same(up.GetElement(lane), UpReference(x[lane])), $"four-lane Up({x[lane]:R}) = {up.GetElement(lane):R}");
      }
    }
  }

  // The slab test one axis at a time, with early exits, as it was written before the set-up was vectorized.
  static bool SlabReference(double min, double max, double o, double d, double inv, ref double tMin, ref double tMax)
  {
    if (d == 0.0)
      return o >= min && o <= max;
    double t0 = (min - o) * inv, t1 = (max - o) * inv;
    if (t0 > t1)
      (t0, t1) = (t1, t0);
    double pad = 1e-12 * (Math.Abs(t0) + Math.Abs(t1));
    tMin = Math.Max(tMin, t0 - pad);
    tMax = Math.Min(tMax, t1 + pad);
    return tMin <= tMax;
  }

  static bool LineBoxReference(in BvhNode b, in MeshLine l, out double tMin, out double tMax)
  {
    tMin = double.NegativeInfinity;
    tMax = double.PositiveInfinity;
    return SlabReference(b.MinX, b.MaxX, l.Ox, l.Dx, l.Ix, ref tMin, ref tMax) &&
           SlabReference(b.MinY, b.MaxY, l.Oy, l.Dy, l.Iy, ref tMin, ref tMax) &&
           SlabReference(b.MinZ, b.MaxZ, l.Oz, l.Dz, l.Iz, ref tMin, ref tMax);
  }

  static double Coordinate(Random r, double lo, double hi) => r.Next(6) switch
  {
    0 => lo,
    1 => hi,
    2 => r.Next(2) == 0 ? 0.0 : -0.0,
    3 => Sample(r),
    _ => lo + (hi - lo) * (r.NextDouble() * 3.0 - 1.0),
  };

  static double Direction(Random r) => r.Next(6) switch
  {
    0 => r.Next(2) == 0 ? 0.0 : -0.0,
    1 => Sample(r),
    2 => (r.NextDouble() - 0.5) * 1e-30,
    _ => r.NextDouble() - 0.5,
  };

  [Fact]
  public void The_lines_interval_in_the_mesh_box_is_the_one_slab_by_slab()
  {
    var r = new Random(4242);
    int crossing = 0;
    for (int i = 0; i < 300_000; i++)
    {
      double s = Math.Pow(10, r.Next(-20, 20));
      var box = new BvhNode { MinX = -s, MaxX = s * r.NextDouble(), MinY = -2 * s, MaxY = -s, MinZ = 0.0, MaxZ = r.Next(4) == 0 ? 0.0 : s };
      if (r.Next(50) == 0)
        box.MaxX = double.NaN;
      var line = new MeshLine(Coordinate(r, box.MinX, box.MaxX), Coordinate(r, box.MinY, box.MaxY), Coordinate(r, box.MinZ, box.MaxZ),
                              Direction(r), Direction(r), Direction(r));
      bool want = LineBoxReference(box, line, out double wantMin, out double wantMax);
      bool got = MeshBvh.LineBox(box, line, out double gotMin, out double gotMax);
      Assert.Equal(want, got);
      if (want)
      {
        crossing++;
        Assert.Equal(BitConverter.DoubleToInt64Bits(wantMin), BitConverter.DoubleToInt64Bits(gotMin));
        Assert.Equal(BitConverter.DoubleToInt64Bits(wantMax), BitConverter.DoubleToInt64Bits(gotMax));
      }
    }
    Assert.InRange(crossing, 30_000, 270_000);   // both answers well represented
  }
}
