using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Local reflectance (a BRDF-like model) of a surface point.</summary>
public interface IReflectanceModel
{
  /// <summary>A new material with this model's default coefficients, for solids that have no <see cref="PropertyName.MATERIAL"/> attribute.</summary>
  IMaterial DefaultMaterial();

  /// <summary>Reflected colour for light arriving along <paramref name="input"/> and leaving along <paramref name="output"/>; null for none.</summary>
  double[]? ColorReflection(Intersection intersection, Vector3d input, Vector3d output, ReflectionComponent comp);

  /// <summary>
  /// Reflected colour per band for a given material and normal (without the light's intensity, which the caller
  /// multiplies in); null when there is none or the model does not know the material.
  /// </summary>
  /// <param name="material">The surface material.</param>
  /// <param name="normal">Unit surface normal.</param>
  /// <param name="input">From the surface point towards the light, any length; zero for ambient light.</param>
  /// <param name="output">Unit direction from the surface point towards the viewer.</param>
  /// <param name="comp">Which parts to compute (flags).</param>
  double[]? ColorReflection(IMaterial material, Vector3d normal, Vector3d input, Vector3d output, ReflectionComponent comp);
}
