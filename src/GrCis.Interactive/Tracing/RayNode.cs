using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Observation;

namespace GrCis.Interactive;

/// <summary>One ray of a probed pixel, with the rays it spawned (shadow rays, mirrored, refracted).</summary>
public sealed class RayNode
{
  internal RayNode(RayKind kind, int depth, Vector3d origin, Vector3d direction)
  {
    Kind = kind;
    Depth = depth;
    Origin = origin;
    Direction = direction;
  }

  public RayKind Kind { get; }

  /// <summary>Recursion depth: 0 for the primary ray and its shadow rays.</summary>
  public int Depth { get; }

  public Vector3d Origin { get; }

  /// <summary>As traced (shadow rays: not normalised, reaching the light at t = 1).</summary>
  public Vector3d Direction { get; }

  /// <summary>World position of the first hit; null when the ray missed (or, for a shadow ray, reached the light).</summary>
  public Vector3d? Hit { get; internal set; }

  /// <summary>Normal at the hit (facing the ray), for shaded rays that hit.</summary>
  public Vector3d? Normal { get; internal set; }

  /// <summary>The solid hit, if any.</summary>
  public ISolid? Solid { get; internal set; }

  /// <summary>Shadow rays: the light is blocked.</summary>
  public bool Blocked { get; internal set; }

  public List<RayNode> Children { get; } = new();

  /// <summary>This node and all below it, depth first.</summary>
  public IEnumerable<RayNode> Flatten()
  {
    yield return this;
    foreach (RayNode c in Children)
      foreach (RayNode d in c.Flatten())
        yield return d;
  }

  public override string ToString()
  {
    string hit = Hit is Vector3d h ? System.FormattableString.Invariant($"hit ({h.X:0.###}, {h.Y:0.###}, {h.Z:0.###})") : "miss";
    if (Kind == RayKind.Shadow)
      hit = Blocked ? hit.Replace("hit", "blocked at") : "light visible";
    return System.FormattableString.Invariant(
      $"{Kind} d{Depth} from ({Origin.X:0.###}, {Origin.Y:0.###}, {Origin.Z:0.###}) dir ({Direction.X:0.###}, {Direction.Y:0.###}, {Direction.Z:0.###}): {hit}");
  }
}
