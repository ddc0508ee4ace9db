using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The one light model of the Monte Carlo integrators (after pbrt-v4's <c>Light::SampleLi</c>/<c>PdfLi</c>): GrCis's
/// public <see cref="ILightSource"/>s, the emissive surfaces and the background all answer through it.
/// Implementations are made per worker (they may keep buffers) by <see cref="SceneLights"/>.
/// </summary>
internal interface ILight
{
  LightKind Kind { get; }

  /// <summary>An estimate of the light's power (flux), for choosing among lights; only the variance depends on it.</summary>
  double Power { get; }

  /// <summary>A sample of the light arriving at <paramref name="ctx"/> from (u, v) in [0,1)²; false when none arrives.</summary>
  bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample);

  /// <summary>
  /// The density per solid angle with which <see cref="SampleLi"/> from <paramref name="ctx"/> gives the unit direction
  /// <paramref name="wi"/> that reached this light at <paramref name="point"/> (surface normal <paramref name="normal"/>);
  /// 0 for a delta light or a direction it never gives.
  /// </summary>
  double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal);

  /// <summary>Radiance a ray of unit <paramref name="direction"/> gets when it reaches the light where its surface normal is <paramref name="normal"/> (zero for a delta light).</summary>
  Rgb Le(in Vector3d normal, in Vector3d direction);
}
