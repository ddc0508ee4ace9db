using System;

namespace Rendering;

/// <summary>
/// <see cref="Strata"/>'s patterns for one sample count, with what depends on the count alone worked out once: the
/// m×n grid, the masks of the permutations' power-of-two ranges and the divisions by the count, m and n (a shift or
/// mask for powers of two, else a multiply by a precomputed reciprocal; the final scalings to [0,1) a product when the
/// count is a power of two, exact then). <see cref="Sample1D"/> and
/// <see cref="Sample2D"/> give the same bits as <see cref="Strata.Sample1D(int, int, uint)"/> and
/// <see cref="Strata.Sample2D(int, int, uint, out double, out double)"/>; a sampler keeps one while the count stays.
/// </summary>
internal readonly struct StrataGrid
{
  /// <summary>The sample count (at least 1).</summary>
  public readonly int Total;

  readonly Divisor total, m, n;

  // 1/count, 1/m and 1/n when all three are powers of two: a product by them is then the quotient's exact bits.
  readonly double inverseTotal, inverseM, inverseN;
  readonly bool powers;

  public StrataGrid(int count)
  {
    Total = Math.Max(count, 1);
    // The grid of Strata.Sample2D.
    int columns = Strata.GridColumns(Total);
    total = new Divisor((uint)Total);
    m = new Divisor((uint)columns);
    n = new Divisor((uint)(Total / columns));
    powers = m.IsPowerOfTwo && n.IsPowerOfTwo;
    inverseTotal = 1.0 / Total;
    inverseM = 1.0 / m.Value;
    inverseN = 1.0 / n.Value;
  }

  /// <summary><see cref="Strata.Sample1D(int, int, uint)"/> for this count.</summary>
  public double Sample1D(int rank, uint pattern)
  {
    uint s = Permute((uint)Math.Clamp(rank, 0, Total - 1), total, pattern * 0x51633E2Du);
    double x = s + Strata.Jitter(s, pattern * 0x68BC21EBu);
    return powers ? x * inverseTotal : x / Total;
  }

  /// <summary><see cref="Strata.Sample2D(int, int, uint, out double, out double)"/> for this count.</summary>
  public void Sample2D(int rank, uint pattern, out double u, out double v)
  {
    uint s = Permute((uint)Math.Clamp(rank, 0, Total - 1), total, pattern * 0x51633E2Du);
    uint row = m.Div(s), column = s - row * m.Value;
    uint sx = Permute(column, m, pattern * 0x68BC21EBu);
    uint sy = Permute(row, n, pattern * 0x02E5BE93u);
    double jx = Strata.Jitter(s, pattern * 0x967A889Bu);
    double jy = Strata.Jitter(s, pattern * 0x3C6EF372u);
    if (powers)
    {
      u = (column + (sy + jx) * inverseN) * inverseM;
      v = (row + (sx + jy) * inverseM) * inverseN;
      return;
    }
    int mi = (int)m.Value, ni = (int)n.Value;
    u = (column + (sy + jx) / ni) / mi;
    v = (row + (sx + jy) / mi) / ni;
  }

  /// <summary><see cref="Strata.Permute"/> with the range's mask and the final division precomputed.</summary>
  static uint Permute(uint i, in Divisor length, uint p)
  {
    if (length.Value <= 1)
      return 0;
    uint w = length.Mask;
    do
      i = Strata.PermuteRound(i, w, p);
    while (i >= length.Value);
    return length.Mod(i + p);
  }

  /// <summary>
  /// Exact division and remainder of 32-bit numbers by a fixed divisor: a shift and a mask for a power of two, else
  /// Lemire, Kaser and Kurz's direct remainder (Faster remainder by direct computation, 2019) with the 64-bit
  /// reciprocal ⌈2⁶⁴/d⌉, exact for every 32-bit dividend and divisor.
  /// </summary>
  internal readonly struct Divisor
  {
    public readonly uint Value;

    /// <summary>The smallest all-ones mask covering 0..Value−1 (the permutation's range).</summary>
    public readonly uint Mask;

    readonly ulong reciprocal;
    readonly int shift;
    readonly bool power;

    public bool IsPowerOfTwo => power;

    public Divisor(uint d)
    {
      if (d == 0)
        throw new ArgumentOutOfRangeException(nameof(d), "A divisor must be positive.");
      Value = d;
      Mask = Strata.RangeMask(d);
      power = (d & (d - 1)) == 0;
      shift = System.Numerics.BitOperations.TrailingZeroCount(d);
      reciprocal = power ? 0UL : ulong.MaxValue / d + 1UL;
    }

    public uint Div(uint a) => power ? a >> shift : (uint)Math.BigMul(reciprocal, a, out _);

    public uint Mod(uint a) => power ? a & (Value - 1) : (uint)Math.BigMul(reciprocal * a, Value, out _);
  }
}
