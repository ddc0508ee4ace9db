namespace Rendering.Tessellation;

/// <summary>The kind of a light in a <see cref="SceneTessellation"/>.</summary>
public enum TessellatedLightKind
{
  /// <summary>A point light (<see cref="PointLightSource"/>, or a script's light with a position).</summary>
  Point,

  /// <summary>A rectangle light, given by its centre and its two edge vectors.</summary>
  Rectangle,

  /// <summary>A sphere light, given by its centre and radius.</summary>
  Sphere,
}
