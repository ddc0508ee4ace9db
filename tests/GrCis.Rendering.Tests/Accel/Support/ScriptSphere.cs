using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Testing;

/// <summary>A solid the library does not know (as a scene script would declare): LinkedList API only.</summary>
public sealed class ScriptSphere : DefaultSceneNode, ISolid
{
  readonly RefSphere geometry = new();

  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    LinkedList<Intersection>? list = geometry.Intersect(p0, p1);
    if (list != null)
      foreach (Intersection i in list)
        i.Solid = this;
    return list;
  }

  public override void CompleteIntersection(Intersection inter) => geometry.CompleteIntersection(inter);

  public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2) => geometry.GetBoundingBox(out corner1, out corner2);
}
