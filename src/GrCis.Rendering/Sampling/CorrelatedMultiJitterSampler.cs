namespace Rendering;

/// <summary>
/// Correlated multi-jitter (Kensler 2013, <see cref="Strata"/>): within a pixel, the samples of one dimension are
/// stratified in 2D and in each coordinate alone, and different dimensions are independent shuffles. The default
/// sampler; its values are those <see cref="Strata"/> gave before samplers were objects, so images are unchanged.
/// </summary>
public sealed class CorrelatedMultiJitterSampler : Sampler
{
  public override SamplerKind Kind => SamplerKind.CorrelatedMultiJitter;

  public override double Get1D(SampleDimension dimension, int instance = 0) =>
    Grid().Sample1D(Index, Pattern(dimension, instance));

  public override void Get2D(SampleDimension dimension, int instance, out double u, out double v) =>
    Grid().Sample2D(Index, Pattern(dimension, instance), out u, out v);

  long hashedSeed;
  ulong seedHash = Strata.SeedHash(0);
  StrataGrid grid = new(1);

  /// <summary>The pattern constants of the current sample count, worked out again only when the count changes.</summary>
  ref readonly StrataGrid Grid()
  {
    if (grid.Total != System.Math.Max(Count, 1))
      grid = new StrataGrid(Count);
    return ref grid;
  }

  /// <summary>The pattern of a dimension in the current pixel (the hash <see cref="Strata"/> has always used).</summary>
  public uint Pattern(SampleDimension dimension, int instance = 0)
  {
    // The seed's part of the hash is kept while the seed stays (the same values, one hash less per call).
    if (Seed != hashedSeed)
    {
      seedHash = Strata.SeedHash(Seed);
      hashedSeed = Seed;
    }
    return Strata.Pattern(seedHash, Frame, X, Y, Strata.Dimension((uint)dimension, instance));
  }
}
