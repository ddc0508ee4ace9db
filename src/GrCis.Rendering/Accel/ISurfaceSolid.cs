using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// A solid that can complete a hit for the library's own shading alone (<see cref="HitCompletion.OwnSurface"/>): the
/// normal and texture coordinates its full completion computes, to the bit, without the tangents. The library's
/// triangle mesh has one; the prepared scene uses it only for a class that changes nothing of the class implementing it.
/// </summary>
internal interface ISurfaceSolid
{
  /// <summary>
  /// Sets <see cref="Intersection.NormalLocal"/>, <see cref="Intersection.Normal"/> (not yet unit length) and
  /// <see cref="Intersection.TextureCoord"/> of a hit begun by <see cref="Intersection.BeginSurface"/>; false, with
  /// nothing written, when this hit needs the full completion after all.
  /// </summary>
  bool CompleteSurface(Intersection inter, in Matrix4d worldToLocal);
}
