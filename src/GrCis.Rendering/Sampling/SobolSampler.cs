using MathSupport;

namespace Rendering;

/// <summary>
/// Owen-scrambled Sobol points, "padded" (as pbrt-v4's PaddedSobolSampler): each dimension of a pixel takes the
/// first two Sobol dimensions, its sample indices shuffled and its points scrambled by a key of its own
/// (seed, frame, pixel, dimension, instance). With a power-of-two sample count the pixel's points of one
/// dimension are a (0,2)-net: stratified in every elementary interval of the count's area, not only on a grid.
/// </summary>
/// <remarks>
/// Sobol dimension 0 is the van der Corput sequence (the index's bits reversed). Dimension 1 comes from the
/// primitive polynomial x + 1 with initial direction number m₁ = 1, the first row of Joe and Kuo's table
/// (new-joe-kuo-6.21201, "d=2 s=1 a=0 m_i=1"; S. Joe and F. Y. Kuo, Constructing Sobol sequences with better
/// two-dimensional projections, SIAM J. Sci. Comput. 30, 2008): mₖ = 2mₖ₋₁ ⊕ mₖ₋₁, vₖ = mₖ / 2ᵏ. Only these
/// two dimensions are needed. The scramble is the hash-based nested uniform scramble of Burley, Practical
/// Hash-based Owen Scrambling (JCGT 9(4), 2020), in its Laine-Karras form.
/// </remarks>
public sealed class SobolSampler : Sampler
{
  /// <summary>Direction numbers of Sobol dimension 1 as 32-bit fractions (bit 31 = 1/2).</summary>
  static readonly uint[] Directions1 = MakeDirections1();

  /// <inheritdoc/>
  public override SamplerKind Kind => SamplerKind.Sobol;

  /// <inheritdoc/>
  public override double Get1D(SampleDimension dimension, int instance = 0)
  {
    ulong key = PixelKey(dimension, instance, 0x452821E638D01377UL);
    uint i = ShuffledIndex(key);
    return ToUnit(Scramble(Sobol(0, i), (uint)(key >> 32)), key);
  }

  /// <inheritdoc/>
  public override void Get2D(SampleDimension dimension, int instance, out double u, out double v)
  {
    ulong key = PixelKey(dimension, instance, 0x452821E638D01377UL);
    uint i = ShuffledIndex(key);
    ulong key2 = RandomStatic.Mix64(key);
    u = ToUnit(Scramble(Sobol(0, i), (uint)(key >> 32)), key);
    v = ToUnit(Scramble(Sobol(1, i), (uint)(key2 >> 32)), key2);
  }

  /// <summary>Point <paramref name="index"/> of Sobol dimension <paramref name="dimension"/> (0 or 1), as a 32-bit fraction, unscrambled.</summary>
  public static uint Sobol(int dimension, uint index)
  {
    if (dimension == 0)
      return ReverseBits(index);
    uint x = 0;
    for (int k = 0; index != 0; k++, index >>= 1)
      if ((index & 1) != 0)
        x ^= Directions1[k];
    return x;
  }

  /// <summary>The current sample's index in this dimension's order: a shuffle of the pixel's indices (a permutation of 0..Count−1).</summary>
  uint ShuffledIndex(ulong key)
  {
    int count = Count < 1 ? 1 : Count;
    int index = Index < 0 ? 0 : Index >= count ? count - 1 : Index;
    return Strata.Permute((uint)index, (uint)count, (uint)key);
  }

  /// <summary>
  /// Nested uniform scramble of a 32-bit fraction: each bit is flipped by a hash of the bits above it (the Laine-Karras
  /// permutation applied to the reversed bits, where "above" becomes "below"), so points stay in their strata.
  /// </summary>
  static uint Scramble(uint x, uint seed)
  {
    x = ReverseBits(x);
    x ^= x * 0x3D20ADEAu;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526C56u;
    x ^= x * 0x53A22864u;
    return ReverseBits(x);
  }

  /// <summary>A 32-bit fraction as a double of [0,1), with its lower bits filled from the key so no two points tie.</summary>
  static double ToUnit(uint x, ulong key) => (x + (RandomStatic.Mix64(key ^ x) >> 43) * (1.0 / (1 << 21))) * (1.0 / 4294967296.0);

  static uint ReverseBits(uint x)
  {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00FF00FFu) << 8) | ((x & 0xFF00FF00u) >> 8);
    x = ((x & 0x0F0F0F0Fu) << 4) | ((x & 0xF0F0F0F0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xCCCCCCCCu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xAAAAAAAAu) >> 1);
    return x;
  }

  static uint[] MakeDirections1()
  {
    var v = new uint[32];
    uint m = 1;   // m₁ (Joe and Kuo, dimension 2)
    for (int k = 0; k < 32; k++)
    {
      v[k] = m << (31 - k);
      m = (m << 1) ^ m;   // x + 1: mₖ = 2mₖ₋₁ ⊕ mₖ₋₁
    }
    return v;
  }
}
