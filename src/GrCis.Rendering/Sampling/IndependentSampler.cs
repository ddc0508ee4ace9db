using MathSupport;

namespace Rendering;

/// <summary>
/// Independent uniform numbers: every value a separate hash of (seed, frame, pixel, dimension, instance, sample
/// index). No stratification at all, the reference the stratified samplers are measured against.
/// </summary>
public sealed class IndependentSampler : Sampler
{
  /// <inheritdoc/>
  public override SamplerKind Kind => SamplerKind.Independent;

  /// <inheritdoc/>
  public override double Get1D(SampleDimension dimension, int instance = 0) =>
    Unit(RandomStatic.Mix64(PixelKey(dimension, instance, 0x243F6A8885A308D3UL) ^ (uint)Index));

  /// <inheritdoc/>
  public override void Get2D(SampleDimension dimension, int instance, out double u, out double v)
  {
    ulong h = RandomStatic.Mix64(PixelKey(dimension, instance, 0x243F6A8885A308D3UL) ^ (uint)Index);
    u = Unit(h);
    v = Unit(RandomStatic.Mix64(h ^ 0x13198A2E03707344UL));
  }
}
