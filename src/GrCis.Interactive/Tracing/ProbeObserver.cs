using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Observation;

namespace GrCis.Interactive;

/// <summary>Builds the ray tree of one probed sample (single thread).</summary>
internal sealed class ProbeObserver : RayObserver
{
  readonly IRayScene scene;
  readonly Stack<RayNode> open = new();

  public ProbeObserver(IRayScene scene) => this.scene = scene;

  public RayNode? Root { get; private set; }

  public override void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction)
  {
    var node = new RayNode(kind, depth, origin, direction);
    if (open.Count == 0)
      Root ??= node;
    else
      open.Peek().Children.Add(node);
    open.Push(node);
  }

  public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
  {
    RayNode node = open.Pop();
    if (hit != null)
    {
      node.Hit = hit.CoordWorld;
      node.Normal = hit.Normal;
      node.Solid = hit.Solid;
    }
  }

  public override void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked)
  {
    var node = new RayNode(RayKind.Shadow, open.Count > 0 ? open.Peek().Depth : 0, origin, direction) { Blocked = blocked };
    if (blocked)
    {
      // Probe only: ask the scene again for where the shadow ray stopped.
      Vector3d d = direction;
      Intersection? si = Intersection.FirstRealIntersection(scene.Intersectable?.Intersect(origin, d), ref d);
      if (si != null)
      {
        node.Hit = origin + si.T * direction;
        node.Solid = si.Solid;
      }
    }
    if (open.Count > 0)
      open.Peek().Children.Add(node);
    else
      Root ??= node;
  }
}
