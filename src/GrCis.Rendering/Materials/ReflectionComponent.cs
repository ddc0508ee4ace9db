namespace Rendering;

/// <summary>Which parts of the reflectance a query asks for (flags).</summary>
[System.Flags]
public enum ReflectionComponent
{
  DIFFUSE = 1,
  SPECULAR_REFLECTION = 2,
  SPECULAR_REFRACTION = 4,
  SPECULAR = 6,
  ALL = 7,
}
