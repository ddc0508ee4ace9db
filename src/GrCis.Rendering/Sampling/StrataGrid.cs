using System;

namespace Rendering;

/// <summary>
/// What <see cref="Strata.Sample2D(int, int, uint, out double, out double)"/> derives from the sample count alone (the
/// m×n grid and the divisions by the count, m and n), computed once per count: a sampler keeps it while its count stays.
/// </summary>
internal readonly struct StrataGrid
{
  /// <summary>The sample count (at least 1), its grid's columns m and rows n (m·n = count).</summary>
  public readonly FastDivisor Total, M, N;

  public StrataGrid(int total)
  {
    total = Math.Max(total, 1);
    // The same grid as Strata.Sample2D: m the largest divisor of the count not above its square root.
    int m = (int)Math.Sqrt(total);
    while (total % m != 0)
      m--;
    Total = new FastDivisor((uint)total);
    M = new FastDivisor((uint)m);
    N = new FastDivisor((uint)(total / m));
  }
}
