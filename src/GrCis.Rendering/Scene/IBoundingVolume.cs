using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A cheap conservative test: -1 miss, 0 origin inside, otherwise the entry t.</summary>
public interface IBoundingVolume
{
  double Intersect(Vector3d p0, Vector3d p1);
}
