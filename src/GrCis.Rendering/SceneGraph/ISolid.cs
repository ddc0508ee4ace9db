using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A leaf object defined in its own local coordinate system.</summary>
public interface ISolid : ISceneNode
{
  /// <summary>
  /// Axis-aligned box of the solid in local coordinates; an unbounded side is ±<see cref="DefaultSceneNode.INFINITY_PLACEHOLDER"/>.
  /// GrCis added it on 2019-09-29; a solid written before has no box of its own and answers the whole space
  /// (the scene preparation never trusts the box of a solid it does not know, so such a solid is always tested).
  /// </summary>
  void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    double p = DefaultSceneNode.INFINITY_PLACEHOLDER;
    corner1 = new Vector3d(-p, -p, -p);
    corner2 = new Vector3d(p, p, p);
  }
}
