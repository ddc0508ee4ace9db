using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A leaf object defined in its own local coordinate system.</summary>
public interface ISolid : ISceneNode
{
  /// <summary>Axis-aligned box of the solid in local coordinates (may be infinite).</summary>
  void GetBoundingBox(out Vector3d corner1, out Vector3d corner2);
}
