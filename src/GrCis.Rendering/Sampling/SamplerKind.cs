namespace Rendering;

/// <summary>The sample generators a render may use (<see cref="Sampler.Create"/>; <c>--sampler</c>).</summary>
public enum SamplerKind
{
  /// <summary>Correlated multi-jitter (<see cref="CorrelatedMultiJitterSampler"/>), the default.</summary>
  CorrelatedMultiJitter,

  /// <summary>Independent uniform numbers (<see cref="IndependentSampler"/>).</summary>
  Independent,

  /// <summary>Owen-scrambled Sobol points (<see cref="SobolSampler"/>).</summary>
  Sobol,
}
