using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An emissive surface that light sampling does not reach (an emissive solid under an intersection or difference, an
/// ellipsoid, a <see cref="SphereFront"/>, any solid <see cref="EmitterSet"/> does not sample) in the light model: found
/// only by rays that hit it, so it has no power to be chosen by and no density. It emits its material's
/// <see cref="PhongMaterial.Emission"/> (read when hit, so a change between frames shows) on the side its normal points to.
/// </summary>
internal sealed class EmissiveSurface : ILight
{
  readonly PhongMaterial material;

  public EmissiveSurface(PhongMaterial material) => this.material = material;

  public LightKind Kind => LightKind.Area;

  /// <summary>0: never chosen for light sampling.</summary>
  public double Power => 0.0;

  public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample)
  {
    sample = default;
    return false;
  }

  public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) => 0.0;

  public Rgb Le(in Vector3d normal, in Vector3d direction) =>
    material.Emission is double[] emission && Vector3d.Dot(normal, direction) < 0.0 ? Rgb.From(emission) : Rgb.Zero;
}
