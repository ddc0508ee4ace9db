using System;
using System.Runtime.Intrinsics;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

public class BvhChildBoxesTests
{
  static readonly double[] Specials =
  {
    0.0, -0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, double.PositiveInfinity, double.NegativeInfinity, double.NaN, 2.5, -3.25,
  };

  static BvhNode Box(Random r, bool special)
  {
    double Coord() => special && r.Next(4) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 8.0 - 4.0;
    double x0 = Coord(), x1 = Coord(), y0 = Coord(), y1 = Coord(), z0 = Coord(), z1 = Coord();
    // Mostly proper boxes, sometimes inverted (empty) or degenerate (flat) ones.
    if (r.Next(5) != 0)
    {
      (x0, x1) = (Math.Min(x0, x1), Math.Max(x0, x1));
      (y0, y1) = (Math.Min(y0, y1), Math.Max(y0, y1));
      (z0, z1) = (Math.Min(z0, z1), Math.Max(z0, z1));
    }
    if (r.Next(10) == 0)
      x1 = x0;
    return new BvhNode { MinX = x0, MaxX = x1, MinY = y0, MaxY = y1, MinZ = z0, MaxZ = z1 };
  }

  [Fact]
  public void Two_box_simd_test_answers_as_the_scalar_slab_test_for_each_box()
  {
    var r = new Random(1234);
    int hits = 0, misses = 0;
    for (int n = 0; n < 200_000; n++)
    {
      bool special = n % 3 == 0;
      BvhNode a = Box(r, special), b = Box(r, special);
      double Origin() => special && r.Next(6) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 12.0 - 6.0;
      double Dir() => special && r.Next(3) == 0 ? Specials[r.Next(Specials.Length)] : r.NextDouble() * 2.0 - 1.0;
      double ox = Origin(), oy = Origin(), oz = Origin();
      // Inverse directions as the traversal makes them (zero → 1e-300), plus raw ±∞ and NaN.
      double ix = 1.0 / Dir(), iy = 1.0 / Dir(), iz = 1.0 / Dir();
      if (n % 2 == 1)
      {
        // Aimed at the first box's centre: plenty of hits.
        ix = 1.0 / (0.5 * (a.MinX + a.MaxX) - ox);
        iy = 1.0 / (0.5 * (a.MinY + a.MaxY) - oy);
        iz = 1.0 / (0.5 * (a.MinZ + a.MaxZ) - oz);
      }
      if (n % 7 == 0)
        ox = a.MinX; // origin on a slab plane: 0 · ∞ when the direction is parallel
      double best = n % 5 switch
      {
        0 => double.PositiveInfinity,
        1 => r.NextDouble() * 3.0,
        2 => 0.0,
        3 => double.NaN,
        _ => 1.0 + 1e-12,
      };

      var pair = new BvhChildBoxes(a, b);
      int bits = pair.Hit(Vector128.Create(ox), Vector128.Create(oy), Vector128.Create(oz),
                          Vector128.Create(ix), Vector128.Create(iy), Vector128.Create(iz), best, out Vector128<double> entry);
      bool ha = BvhChildBoxes.Slab(a, ox, oy, oz, ix, iy, iz, best, out double ea);
      bool hb = BvhChildBoxes.Slab(b, ox, oy, oz, ix, iy, iz, best, out double eb);
      Assert.Equal(ha, (bits & 1) != 0);
      Assert.Equal(hb, (bits & 2) != 0);
      // The entry t is re-checked against a smaller best after a push: it must compare the same way.
      if (ha)
        Assert.True(entry.GetElement(0) == ea, $"left entry {entry.GetElement(0)} vs {ea}");
      if (hb)
        Assert.True(entry.GetElement(1) == eb, $"right entry {entry.GetElement(1)} vs {eb}");
      if (ha) hits++; else misses++;
    }
    // Both outcomes occur often enough for the comparison to mean something.
    Assert.True(hits > 10_000 && misses > 10_000, $"{hits} hits, {misses} misses");
  }
}
