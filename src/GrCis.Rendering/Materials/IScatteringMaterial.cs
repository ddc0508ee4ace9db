using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A material that supplies its own scattering to the path tracer (optional: a material without it scatters by its
/// Phong parameters, <see cref="PhongMaterial"/>'s Kd, Ks, H, Kt and n). Directions are unit vectors pointing away
/// from the surface point: <c>wo</c> towards the previous vertex, <c>wi</c> towards the light. Whitted and
/// distributed ray tracing do not read it.
/// </summary>
public interface IScatteringMaterial
{
  /// <summary>The BSDF f(wo, wi) at <paramref name="hit"/> (without the cosine), one value per band into <paramref name="f"/>; zero for delta lobes.</summary>
  void Eval(Intersection hit, Vector3d wo, Vector3d wi, double[] f);

  /// <summary>The density per steradian with which <see cref="Sample"/> gives <paramref name="wi"/> (0 for directions only a delta lobe gives).</summary>
  double Pdf(Intersection hit, Vector3d wo, Vector3d wi);

  /// <summary>
  /// Samples <paramref name="wi"/> from the random numbers <paramref name="choice"/>, <paramref name="u"/>, <paramref name="v"/>
  /// in [0,1): <paramref name="weight"/> gets f·|cos θi|/pdf per band, <paramref name="pdf"/> the density
  /// (<paramref name="delta"/> true and pdf 0 for a delta lobe). False when the sample carries nothing.
  /// </summary>
  bool Sample(Intersection hit, Vector3d wo, double choice, double u, double v, out Vector3d wi, double[] weight, out double pdf, out bool delta);
}
