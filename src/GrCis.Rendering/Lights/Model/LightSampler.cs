using System;
using System.Collections.Generic;

namespace Rendering;

/// <summary>
/// Chooses one light in proportion to its <see cref="ILight.Power"/> (lights of no power are never chosen), and tells
/// the probability of a given light, which the MIS weight of a ray that hits it needs.
/// </summary>
internal sealed class LightSampler
{
  readonly ILight[] lights;
  readonly double[] cdf, pmf;
  readonly Dictionary<ILight, int> index = new(ReferenceEqualityComparer.Instance);

  public LightSampler(IReadOnlyList<ILight> all)
  {
    var kept = new List<ILight>();
    double total = 0.0;
    foreach (ILight light in all)
    {
      double p = light.Power;
      if (p > 0.0 && double.IsFinite(p))
      {
        kept.Add(light);
        total += p;
      }
    }
    lights = kept.ToArray();
    cdf = new double[lights.Length];
    pmf = new double[lights.Length];
    double running = 0.0;
    for (int k = 0; k < lights.Length; k++)
    {
      pmf[k] = lights[k].Power / total;
      cdf[k] = (running += lights[k].Power) / total;
      index[lights[k]] = k;
    }
  }

  /// <summary>Lights that may be chosen.</summary>
  public int Count => lights.Length;

  /// <summary>The light for <paramref name="u"/> in [0,1) and the probability it had; null when there is none.</summary>
  public ILight? Sample(double u, out double probability)
  {
    probability = 0.0;
    if (lights.Length == 0)
      return null;
    int k = 0;
    if (lights.Length > 1)
    {
      k = Array.BinarySearch(cdf, u);
      k = Math.Min(k < 0 ? ~k : k, lights.Length - 1);
      // Skip lights of no probability a binary search may land on when cdf values repeat.
      while (k < lights.Length - 1 && pmf[k] == 0.0)
        k++;
    }
    probability = pmf[k];
    return lights[k];
  }

  /// <summary>The probability <see cref="Sample"/> chooses <paramref name="light"/> (0 for one it never chooses).</summary>
  public double Probability(ILight light) => index.TryGetValue(light, out int k) ? pmf[k] : 0.0;
}
