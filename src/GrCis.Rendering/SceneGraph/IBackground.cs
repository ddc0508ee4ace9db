using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Colour of a ray that hits nothing.</summary>
public interface IBackground
{
  /// <summary>Fills <paramref name="color"/> for ray direction <paramref name="p1"/>; returns a hash.</summary>
  long GetColor(Vector3d p1, double[] color);
}
