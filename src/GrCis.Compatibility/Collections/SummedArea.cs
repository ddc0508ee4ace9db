using System;
using System.Numerics;

namespace MathSupport;

/// <summary>Prefix sums over a 2D table and rectangle sums from them, for any integer type.</summary>
internal static class SummedArea
{
  public static void Compute<T>(T[,] t) where T : INumber<T>
  {
    ArgumentNullException.ThrowIfNull(t);
    int xres = t.GetLength(0), yres = t.GetLength(1);
    for (int y = 1; y < yres; y++)
      t[0, y] += t[0, y - 1];
    for (int x = 1; x < xres; x++)
    {
      t[x, 0] += t[x - 1, 0];
      for (int y = 1; y < yres; y++)
        t[x, y] += t[x - 1, y] + t[x, y - 1] - t[x - 1, y - 1];
    }
  }

  public static T Sum<T>(T[,] t, int x1, int x2, int y1, int y2) where T : INumber<T>
  {
    ArgumentNullException.ThrowIfNull(t);
    if (x1 < 0 || x2 < x1 || x2 >= t.GetLength(0) || y1 < 0 || y2 < y1 || y2 >= t.GetLength(1))
      throw new ArgumentOutOfRangeException(nameof(x1), $"[{x1}..{x2}] x [{y1}..{y2}] is not a rectangle inside the {t.GetLength(0)}x{t.GetLength(1)} table.");
    T below = y1 > 0 ? t[x2, y1 - 1] : T.Zero;
    T left = x1 > 0 ? t[x1 - 1, y2] : T.Zero;
    T corner = x1 > 0 && y1 > 0 ? t[x1 - 1, y1 - 1] : T.Zero;
    return t[x2, y2] - below - left + corner;
  }
}
