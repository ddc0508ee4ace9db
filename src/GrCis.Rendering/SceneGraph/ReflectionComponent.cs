namespace Rendering;

/// <summary>Which parts of the reflectance a query asks for (flags).</summary>
[System.Flags]
public enum ReflectionComponent
{
  /// <summary>Diffuse reflection.</summary>
  DIFFUSE = 1,
  /// <summary>The specular highlight about the mirrored direction (light and viewer on the same side).</summary>
  SPECULAR_REFLECTION = 2,
  /// <summary>The specular highlight about the refracted direction (light and viewer on opposite sides of the surface).</summary>
  SPECULAR_REFRACTION = 4,
  /// <summary>Both specular parts.</summary>
  SPECULAR = 6,
  /// <summary>Everything: diffuse and both specular parts.</summary>
  ALL = 7,
}
