namespace Rendering;

/// <summary>
/// Correlated multi-jitter (Kensler 2013, <see cref="Strata"/>): within a pixel, the samples of one dimension are
/// stratified in 2D and in each coordinate alone, and different dimensions are independent shuffles. The default
/// sampler; its values are those <see cref="Strata"/> gave before samplers were objects, so images are unchanged.
/// </summary>
public sealed class CorrelatedMultiJitterSampler : Sampler
{
  /// <inheritdoc/>
  public override SamplerKind Kind => SamplerKind.CorrelatedMultiJitter;

  /// <inheritdoc/>
  public override double Get1D(SampleDimension dimension, int instance = 0) =>
    Grid().Sample1D(Index, Pattern(dimension, instance));

  /// <inheritdoc/>
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
    // A pixel's samples ask for the same few patterns again and again: those of instances below CachedInstances are
    // kept for the pixel (an entry counts while its stamp is the pixel's).
    if (X != stampX || Y != stampY || Seed != stampSeed || Frame != stampFrame)
      NewPixel();
    if ((uint)dimension < CachedDimensions && (uint)instance < CachedInstances)
    {
      int slot = (int)dimension * CachedInstances + instance;
      if (stamps[slot] == stamp)
        return patterns[slot];
      stamps[slot] = stamp;
      return patterns[slot] = Hash(dimension, instance);
    }
    return Hash(dimension, instance);
  }

  const int CachedDimensions = 16, CachedInstances = 64;
  readonly uint[] patterns = new uint[CachedDimensions * CachedInstances];
  readonly int[] stamps = new int[CachedDimensions * CachedInstances];
  int stamp, stampX = int.MinValue, stampY, stampFrame;
  long stampSeed;

  /// <summary>Forgets the patterns of the last pixel (a new stamp; the entries are cleared when the stamps run out).</summary>
  void NewPixel()
  {
    if (stamp == int.MaxValue)
    {
      System.Array.Clear(stamps);
      stamp = 0;
    }
    stamp++;
    stampX = X;
    stampY = Y;
    stampSeed = Seed;
    stampFrame = Frame;
  }

  uint Hash(SampleDimension dimension, int instance)
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
