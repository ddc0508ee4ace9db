using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A cheap volume around a solid, tested before the solid itself.</summary>
public interface IBoundingVolume
{
  /// <summary>
  /// Ray <c>p0 + t p1</c> against the volume: −1 when the ray misses it, 0 when <paramref name="p0"/>
  /// lies inside, otherwise the t of the entry point.
  /// </summary>
  double Intersect(Vector3d p0, Vector3d p1);
}
