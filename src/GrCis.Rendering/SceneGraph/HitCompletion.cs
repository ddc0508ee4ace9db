namespace Rendering.Accel;

/// <summary>
/// How a prepared member's hit is completed. When only the library's own shading reads it (plain
/// <see cref="RayTracing"/>/<see cref="RayCasting"/>, library lights, Phong, at most checker and image textures),
/// the world point, normal, colour, material and — for a texture — the texture coordinates are all that is read,
/// never the tangents or the object coordinates: a surface completion computes just those, with the same arithmetic.
/// </summary>
internal enum HitCompletion : byte
{
  /// <summary>Everything (<see cref="Intersection.CompleteCached"/>).</summary>
  Full,

  /// <summary>A plain <see cref="Sphere"/> without textures: no texture coordinates (two Atan2), no tangents.</summary>
  Sphere,

  /// <summary>A plain <see cref="Sphere"/> with checker or image textures: texture coordinates, no tangents.</summary>
  SphereTextured,

  /// <summary>A plain <see cref="Plane"/> (textured or not): texture coordinates, no tangents.</summary>
  Plane,

  /// <summary>A plain <see cref="Cube"/>: the face's texture coordinates (two copies), no tangents.</summary>
  Cube,

  /// <summary>
  /// The solid's own (<see cref="ISurfaceSolid"/>: a plain <see cref="TriangleMesh"/>): the face's or interpolated normal
  /// and the texture coordinates, no tangents; a hit the solid cannot complete so gets the full completion.
  /// </summary>
  OwnSurface,
}
