using System;
using MathSupport;

namespace Rendering;

/// <summary>
/// Where a render's random decisions come from: a render worker starts each sample of a pixel
/// (<see cref="StartPixel"/>, <see cref="StartPixelSample"/>) and every component asks for the values of a named
/// <see cref="SampleDimension"/> (<see cref="Get1D"/>, <see cref="Get2D(SampleDimension, int, out double, out double)"/>).
/// A value is a pure function of (seed, frame, pixel, sample index, sample count, dimension, instance), so an image
/// does not depend on threads, tiles, passes or the order samples are taken. The worker's sampler also holds the
/// pixel and sample that GrCis's <see cref="MT"/> shows (<c>MT.x</c>, <c>MT.rank</c>, <c>MT.total</c> ...).
/// </summary>
public abstract class Sampler
{
  /// <summary>The user's seed; every value derives from it (<c>MT.seed</c>).</summary>
  public long Seed { get; set; }

  /// <summary>Frame number, mixed in so frames differ (<c>MT.frame</c>).</summary>
  public int Frame { get; set; }

  /// <summary>The current pixel (<c>MT.x</c>, <c>MT.y</c>).</summary>
  public int X { get; set; }

  /// <summary>Row of the current pixel (<c>MT.y</c>).</summary>
  public int Y { get; set; }

  /// <summary>Index of the current sample within its pixel (<c>MT.rank</c>).</summary>
  public int Index { get; set; }

  /// <summary>Samples the pixel takes (<c>MT.total</c>); the stratified samplers spread their values over them.</summary>
  public int Count { get; set; }

  /// <summary>Which generator this is.</summary>
  public abstract SamplerKind Kind { get; }

  /// <summary>Starts pixel (<paramref name="x"/>, <paramref name="y"/>) of <paramref name="count"/> samples at sample 0.</summary>
  public void StartPixel(int x, int y, int count)
  {
    X = x;
    Y = y;
    Count = count;
    Index = 0;
  }

  /// <summary>Starts sample <paramref name="index"/> of pixel (<paramref name="x"/>, <paramref name="y"/>); the count stays.</summary>
  public void StartPixelSample(int x, int y, int index)
  {
    X = x;
    Y = y;
    Index = index;
  }

  /// <summary>A number of [0,1) for the current sample in <paramref name="dimension"/>.</summary>
  /// <param name="instance">Which one of the dimension's uses: the recursion depth or bounce, a light's identity.</param>
  public abstract double Get1D(SampleDimension dimension, int instance = 0);

  /// <summary>A point of [0,1)² for the current sample in <paramref name="dimension"/>.</summary>
  public abstract void Get2D(SampleDimension dimension, int instance, out double u, out double v);

  /// <summary>A point of [0,1)² for the current sample in instance 0 of <paramref name="dimension"/>.</summary>
  public void Get2D(SampleDimension dimension, out double u, out double v) => Get2D(dimension, 0, out u, out v);

  /// <summary>A new sampler of <paramref name="kind"/> for <paramref name="seed"/> and <paramref name="frame"/>.</summary>
  public static Sampler Create(SamplerKind kind, long seed = 0, int frame = 0)
  {
    Sampler s = kind switch
    {
      SamplerKind.CorrelatedMultiJitter => new CorrelatedMultiJitterSampler(),
      SamplerKind.Independent => new IndependentSampler(),
      SamplerKind.Sobol => new SobolSampler(),
      _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown sampler."),
    };
    s.Seed = seed;
    s.Frame = frame;
    return s;
  }

  /// <summary>The name <c>--sampler</c> takes for <paramref name="kind"/>.</summary>
  public static string NameOf(SamplerKind kind) => kind switch
  {
    SamplerKind.Independent => "independent",
    SamplerKind.Sobol => "sobol",
    _ => "cmj",
  };

  /// <summary>The kind named <paramref name="name"/> (cmj, independent, sobol; any case), or false.</summary>
  public static bool TryParse(string? name, out SamplerKind kind)
  {
    foreach (SamplerKind k in Enum.GetValues<SamplerKind>())
      if (string.Equals(name, NameOf(k), StringComparison.OrdinalIgnoreCase))
      {
        kind = k;
        return true;
      }
    kind = SamplerKind.CorrelatedMultiJitter;
    return false;
  }

  /// <summary>A hash of (seed, frame, pixel, dimension, instance): the key of one dimension's values in the current pixel.</summary>
  protected ulong PixelKey(SampleDimension dimension, int instance, ulong salt)
  {
    ulong h = RandomStatic.Mix64((ulong)Seed ^ salt);
    h = RandomStatic.Mix64(h ^ ((ulong)(uint)Frame << 32 | (uint)dimension));
    h = RandomStatic.Mix64(h ^ (uint)instance);
    return RandomStatic.Mix64(h ^ ((ulong)(uint)Y << 32 | (uint)X));
  }

  /// <summary>The top 53 bits of <paramref name="h"/> as a number of [0,1).</summary>
  protected static double Unit(ulong h) => (h >> 11) * (1.0 / (1UL << 53));
}
