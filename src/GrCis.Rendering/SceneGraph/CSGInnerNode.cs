using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An inner node combining its children by a set operation, folded left to right:
/// ((c1 # c2) # c3) … The ray is transformed into each child's space (affine maps keep the
/// ray parameter t), and each binary step merges two sorted hit lists, keeping a hit where
/// the combined inside/outside state changes.
/// </summary>
public class CSGInnerNode : DefaultSceneNode
{
  /// <summary>GrCis's counters of bounding-box and triangle tests; code that tests triangles itself may add to them.</summary>
  public static long countBoundingBoxes;

  /// <summary>GrCis's counter of triangle tests (statistics); the library itself does not add to it.</summary>
  public static long countTriangles;

  /// <summary>GrCis's counter of faces (statistics); the library itself does not add to it, and <see cref="ResetStatistics"/> leaves it as it is.</summary>
  public static long countFaces;

  /// <summary>Zeroes GrCis's statistics counters (rays, intersections, bounding boxes, triangles).</summary>
  public static void ResetStatistics()
  {
    Intersection.countRays = 0L;
    Intersection.countIntersections = 0L;
    countBoundingBoxes = 0L;
    countTriangles = 0L;
  }

  /// <summary>The set operation that combines the children, fixed by the constructor.</summary>
  public SetOperation Operation { get; }

  /// <summary>Optional bounding volume tested before the children.</summary>
  public IBoundingVolume? BoundingVolume;

  /// <summary>An empty left operand empties the result (intersection, difference): stop early.</summary>
  internal readonly bool shortCircuit;

  /// <summary>An empty right operand changes nothing (union, xor, difference): skip it.</summary>
  internal readonly bool trivial;

  /// <summary>An empty inner node; add the operands with <see cref="DefaultSceneNode.InsertChild"/> in order (left to right).</summary>
  /// <param name="op">How the children combine: <see cref="SetOperation.Union"/> for a plain group of objects.</param>
  public CSGInnerNode(SetOperation op)
  {
    Operation = op;
    shortCircuit = !(Result(false, false) || Result(false, true));
    trivial = Result(true, false) && !Result(false, false);
  }

  /// <summary>The set operation on inside flags of the left and right operands.</summary>
  public bool Result(bool left, bool right) => Operation switch
  {
    SetOperation.Union => left || right,
    SetOperation.Intersection => left && right,
    SetOperation.Difference => left && !right,
    _ => left ^ right,
  };

  /// <summary>
  /// All boundaries of the combined solid along the ray <c>p0 + t * p1</c> (in this node's space), sorted by
  /// <see cref="Intersection.T"/>; null when there are no children or the <see cref="BoundingVolume"/> is missed.
  /// Each kept hit's <see cref="Intersection.Enter"/> is set to the inside state of the result after it.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (Children.Count == 0)
      return null;
    if (BoundingVolume != null && BoundingVolume.Intersect(p0, p1) < -0.5)
      return null;

    LinkedList<Intersection>? result = null;
    foreach (ISceneNode child in Children)
    {
      Matrix4d m = child.FromParent;
      LinkedList<Intersection>? partial = child.Intersect(Vector3d.TransformPosition(p0, m), Vector3d.TransformVector(p1, m));

      if (result == null)
        result = partial ?? new LinkedList<Intersection>();
      else if (!(trivial && (partial == null || partial.Count == 0)))
        result = Merge(result, partial);

      if (shortCircuit && result.Count == 0)
        break;
    }
    return result;
  }

  /// <summary>One binary step: boundaries of (left # right), both lists sorted by T.</summary>
  LinkedList<Intersection> Merge(LinkedList<Intersection> left, LinkedList<Intersection>? right)
  {
    var result = new LinkedList<Intersection>();
    LinkedListNode<Intersection>? l = left.First;
    LinkedListNode<Intersection>? r = right?.First;

    // A list that starts with an exit means the ray starts inside that operand.
    bool insideLeft = l != null && !l.Value.Enter;
    bool insideRight = r != null && !r.Value.Enter;
    bool inside = Result(insideLeft, insideRight);

    while (l != null || r != null)
    {
      double tl = l?.Value.T ?? double.PositiveInfinity;
      double tr = r?.Value.T ?? double.PositiveInfinity;
      double t = System.Math.Min(tl, tr);
      Intersection? first = null;

      // On a tie both advance and the left operand's hit represents them.
      if (tr == t)
      {
        first = r!.Value;
        insideRight = first.Enter;
        r = r.Next;
      }
      if (tl == t)
      {
        first = l!.Value;
        insideLeft = first.Enter;
        l = l.Next;
      }

      bool now = Result(insideLeft, insideRight);
      if (now != inside)
      {
        inside = now;
        first!.Enter = now;
        result.AddLast(first);
      }
    }
    return result;
  }
}
