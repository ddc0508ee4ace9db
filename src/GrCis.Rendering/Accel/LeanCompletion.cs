namespace Rendering.Accel;

/// <summary>
/// How a prepared member's hit may be completed when only the library's own shading reads it (plain
/// <see cref="RayTracing"/>/<see cref="RayCasting"/>, library lights, Phong, at most checker textures): those
/// read the world point, normal, colour, material and — for a checker — the texture coordinates, never the
/// tangents or the object coordinates, so a lean completion computes just what is read, with the same arithmetic.
/// </summary>
internal enum LeanCompletion : byte
{
  /// <summary>Full completion (<see cref="Intersection.CompleteCached"/>).</summary>
  None,

  /// <summary>A plain <see cref="Sphere"/> without textures: no texture coordinates (two Atan2), no tangents.</summary>
  Sphere,

  /// <summary>A plain <see cref="Sphere"/> with checker textures: texture coordinates, no tangents.</summary>
  SphereTextured,

  /// <summary>A plain <see cref="Plane"/> (checker floor or none): texture coordinates, no tangents.</summary>
  Plane,

  /// <summary>A plain <see cref="Cube"/>: the face's texture coordinates (two copies), no tangents.</summary>
  Cube,
}
