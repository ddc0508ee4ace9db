using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// One incident-light sample at a shading point: the unit direction <see cref="Wi"/> towards the light, the vector
/// <see cref="ToLight"/> to the light's point (its length <see cref="Distance"/>; infinite for the background), the
/// radiance <see cref="L"/> arriving along it and the density <see cref="Pdf"/> per solid angle (1 for a delta light,
/// whose <see cref="L"/> is then the contribution per unit of BSDF·cos).
/// </summary>
internal readonly struct LightSample
{
  public readonly Rgb L;
  public readonly Vector3d Wi, ToLight;
  public readonly double Distance, Pdf;

  public LightSample(in Rgb l, in Vector3d wi, in Vector3d toLight, double distance, double pdf)
  {
    L = l;
    Wi = wi;
    ToLight = toLight;
    Distance = distance;
    Pdf = pdf;
  }
}
