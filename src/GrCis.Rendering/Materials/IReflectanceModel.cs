using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Local reflectance (a BRDF-like model) of a surface point.</summary>
public interface IReflectanceModel
{
  IMaterial DefaultMaterial();

  /// <summary>Reflected colour for light arriving along <paramref name="input"/> and leaving along <paramref name="output"/>; null for none.</summary>
  double[]? ColorReflection(Intersection intersection, Vector3d input, Vector3d output, ReflectionComponent comp);

  double[]? ColorReflection(IMaterial material, Vector3d normal, Vector3d input, Vector3d output, ReflectionComponent comp);
}
