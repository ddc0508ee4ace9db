using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The size of a scene, for the power of lights that depend on it (the background's flux through the scene): the world
/// box of the solids' local boxes, leaving out unbounded ones (an infinite plane), and the radius of its bounding sphere.
/// </summary>
internal static class SceneBounds
{
  /// <summary>Radius of the sphere around the world box of the bounded solids under <paramref name="root"/>; 0 when there is none.</summary>
  public static double Radius(IIntersectable? root)
  {
    Vector3d min = new(double.PositiveInfinity), max = new(double.NegativeInfinity);
    if (root is ISceneNode node)
      Collect(node, ref min, ref max);
    return min.X <= max.X ? 0.5 * (max - min).Length : 0.0;
  }

  static void Collect(ISceneNode node, ref Vector3d min, ref Vector3d max)
  {
    if (node is ISolid solid)
    {
      solid.GetBoundingBox(out Vector3d a, out Vector3d b);
      if (Bounded(a) && Bounded(b))
      {
        Matrix4d toWorld = solid.ToWorld();
        for (int k = 0; k < 8; k++)
        {
          var corner = new Vector3d((k & 1) == 0 ? a.X : b.X, (k & 2) == 0 ? a.Y : b.Y, (k & 4) == 0 ? a.Z : b.Z);
          Vector3d w = Vector3d.TransformPosition(corner, toWorld);
          if (!double.IsFinite(w.X) || !double.IsFinite(w.Y) || !double.IsFinite(w.Z))
            continue;
          min = Vector3d.ComponentMin(min, w);
          max = Vector3d.ComponentMax(max, w);
        }
      }
    }
    foreach (ISceneNode child in node.Children)
      Collect(child, ref min, ref max);
  }

  /// <summary>False for a corner at the placeholder of an unbounded side (or worse).</summary>
  static bool Bounded(in Vector3d c)
  {
    double limit = 0.5 * DefaultSceneNode.INFINITY_PLACEHOLDER;
    return Math.Abs(c.X) < limit && Math.Abs(c.Y) < limit && Math.Abs(c.Z) < limit;
  }
}
