using System;
using System.Runtime.CompilerServices;
using MathSupport;

namespace Rendering;

/// <summary>
/// Stratified sample points for the current sample of the current pixel (<see cref="MT.rank"/> of
/// <see cref="MT.total"/>): the pixel's samples of one <em>dimension</em> (a lens, a light, a glossy bounce
/// at some depth) together cover [0,1)² stratum by stratum, so 16 samples per pixel give 16 well-spread
/// lens or light points instead of 16 independent random ones. The points are correlated multi-jittered
/// (Kensler 2013): stratified in 2D and in each coordinate alone. They are a pure function of the seed,
/// frame, pixel, dimension and rank, and consume nothing of <see cref="MT.rnd"/>: the image does not depend
/// on threads or on the order the samples are taken. <see cref="CorrelatedMultiJitterSampler"/> is this pattern as
/// a <see cref="Sampler"/>; the members that take a numbered dimension read the current worker's pixel and sample.
/// </summary>
public static class Strata
{
  /// <summary>The dimension of a purpose (a small number chosen by the caller) at a recursion depth.</summary>
  public static uint Dimension(uint purpose, int depth) => purpose * 0x9E3779B9u + (uint)depth * 0x85EBCA6Bu + 1u;

  /// <summary>A point of [0,1)² for the current sample of <paramref name="dimension"/>.</summary>
  public static void Sample2D(uint dimension, out double u, out double v)
  {
    Sampler s = Execution.WorkerContext.Current.Sampler;
    Sample2D(s.Index, s.Count, Pattern(s.Seed, s.Frame, s.X, s.Y, dimension), out u, out v);
  }

  /// <summary>The dimension of a named purpose (<see cref="SampleDimension"/>) at an instance (depth, light).</summary>
  public static uint Dimension(SampleDimension purpose, int instance) => Dimension((uint)purpose, instance);

  /// <summary>A number of [0,1) for the current sample of <paramref name="dimension"/> (stratified over the pixel's samples).</summary>
  public static double Sample1D(uint dimension) => Sample1D(Execution.WorkerContext.Current.Sampler.Index, Execution.WorkerContext.Current.Sampler.Count, Pattern(dimension));

  /// <summary>Sample <paramref name="rank"/> of <paramref name="total"/> of the one-dimensional pattern <paramref name="pattern"/>.</summary>
  public static double Sample1D(int rank, int total, uint pattern)
  {
    total = Math.Max(total, 1);
    uint s = Permute((uint)Math.Clamp(rank, 0, total - 1), (uint)total, pattern * 0x51633E2Du);
    return (s + Jitter(s, pattern * 0x68BC21EBu)) / total;
  }

  /// <summary>
  /// Sample <paramref name="rank"/> of <paramref name="total"/> of the pattern <paramref name="pattern"/>
  /// (any 32-bit value: different patterns are independent shuffles).
  /// </summary>
  public static void Sample2D(int rank, int total, uint pattern, out double u, out double v)
  {
    total = Math.Max(total, 1);
    rank = Math.Clamp(rank, 0, total - 1);
    int m = GridColumns(total), n = total / m;

    uint s = Permute((uint)rank, (uint)total, pattern * 0x51633E2Du);
    uint column = s % (uint)m, row = s / (uint)m;
    uint sx = Permute(column, (uint)m, pattern * 0x68BC21EBu);
    uint sy = Permute(row, (uint)n, pattern * 0x02E5BE93u);
    double jx = Jitter(s, pattern * 0x967A889Bu);
    double jy = Jitter(s, pattern * 0x3C6EF372u);
    u = (column + (sy + jx) / n) / m;
    v = (row + (sx + jy) / m) / n;
  }

  /// <summary>
  /// The columns m of the m×n grid of <paramref name="total"/> samples (total ≥ 1): m·n = total exactly, m the largest
  /// divisor not above √total, so every stratum is used.
  /// </summary>
  internal static int GridColumns(int total)
  {
    int m = (int)Math.Sqrt(total);
    while (total % m != 0)
      m--;
    return m;
  }

  /// <summary>The pattern of a dimension in the current pixel: a hash of seed, frame, pixel and dimension.</summary>
  internal static uint Pattern(uint dimension)
  {
    Sampler s = Execution.WorkerContext.Current.Sampler;
    return Pattern(s.Seed, s.Frame, s.X, s.Y, dimension);
  }

  /// <summary>The pattern of a dimension in pixel (x, y) of a frame: a hash of seed, frame, pixel and dimension.</summary>
  internal static uint Pattern(long seed, int frame, int x, int y, uint dimension) => Pattern(SeedHash(seed), frame, x, y, dimension);

  /// <summary>The first step of <see cref="Pattern(long, int, int, int, uint)"/>, which depends on the seed alone (a sampler keeps it).</summary>
  internal static ulong SeedHash(long seed) => RandomStatic.Mix64((ulong)seed ^ 0xD1B54A32D192ED03UL);

  /// <summary><see cref="Pattern(long, int, int, int, uint)"/> from the seed's <see cref="SeedHash"/>.</summary>
  internal static uint Pattern(ulong seedHash, int frame, int x, int y, uint dimension)
  {
    ulong h = RandomStatic.Mix64(seedHash ^ ((ulong)(uint)frame << 32 | dimension));
    h = RandomStatic.Mix64(h ^ ((ulong)(uint)y << 32 | (uint)x));
    return (uint)(h ^ (h >> 32));
  }

  /// <summary>
  /// A pseudo-random permutation of 0..<paramref name="length"/>−1 chosen by <paramref name="p"/>: an invertible
  /// hash on the smallest power-of-two range that holds the length, walked until it lands inside.
  /// </summary>
  internal static uint Permute(uint i, uint length, uint p)
  {
    if (length <= 1)
      return 0;
    uint w = RangeMask(length);
    do
      i = PermuteRound(i, w, p);
    while (i >= length);
    return (i + p) % length;
  }

  /// <summary>The smallest all-ones mask covering 0..<paramref name="length"/>−1 (the range a permutation walks in).</summary>
  internal static uint RangeMask(uint length)
  {
    uint w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    return w;
  }

  /// <summary>
  /// One round of <see cref="Permute"/>'s hash of <paramref name="i"/> within the all-ones mask <paramref name="w"/>
  /// (<paramref name="p"/> the pattern); rounds repeat until the value falls inside the range (cycle walking).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal static uint PermuteRound(uint i, uint w, uint p)
  {
    // Every step is a bijection on the masked bits (xor with a shifted copy, odd multiply).
    i ^= p;
    i *= 0xE170893Du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929EB3Fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935FA69u;
    i ^= (i & w) >> 11;
    i *= 0x74DCB303u;
    i ^= (i & w) >> 2;
    i *= 0x9E501CC3u;
    i ^= (i & w) >> 2;
    i *= 0xC860A3DFu;
    i &= w;
    i ^= i >> 5;
    return i;
  }

  /// <summary>A number of [0,1) hashed from (i, p), with 53 bits.</summary>
  internal static double Jitter(uint i, uint p)
  {
    ulong h = RandomStatic.Mix64((ulong)p << 32 | i);
    return (h >> 11) * (1.0 / (1UL << 53));
  }
}
