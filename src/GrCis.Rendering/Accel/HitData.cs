using System;

namespace Rendering.Accel;

/// <summary>
/// What the code that shades a hit reads from it, so a query computes no more (as pbrt-v4 separates a
/// ray's intersection from the surface interaction a material needs). Declared by the image function once,
/// when the scene is prepared; a solid that cannot complete a hit partly completes it fully anyway.
/// </summary>
[Flags]
public enum HitData
{
  /// <summary>
  /// T, the world point and normal, Enter/Front, the solid and its cached attributes (reflectance model,
  /// material, colour, textures, recursion function), and the texture coordinates where a texture reads them:
  /// what the library's Phong shading, its lights and <see cref="CheckerTexture"/> read.
  /// </summary>
  Surface = 1,

  /// <summary>Tangents, object and local coordinates, and the hit's three matrices (what user code may read).</summary>
  LocalFrame = 2,

  /// <summary>Everything GrCis's <see cref="Intersection.Complete"/> computes.</summary>
  All = Surface | LocalFrame,
}
