using System;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>The fast path's side of a <see cref="BezierSurface"/> (<see cref="IRecordSolid"/>): the first record from the same search as the list.</summary>
public partial class BezierSurface
{
  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(BezierSurface));

  /// <summary>An open surface: a list may start "inside" (a back face first), so it is tested for every ray.</summary>
  public virtual bool IsClosed => false;

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    Span<Found> found = CollectAll(p0, p1, stackalloc Found[StackHits]);
    for (int k = 0; k < found.Length; k++)
    {
      bool front = Front(found[k], p1);
      if (k == 0)
        insideBefore = !front;
      if (SolidSupport.Accepted(found[k].T, len2))
      {
        Found f = found[k];
        hit.T = f.T;
        hit.CoordLocal = p0 + f.T * p1;
        hit.Data = f.Piece;
        hit.Aux = new Vector3d(f.U, f.V, 0.0);
        hit.Enter = hit.Front = front;
        return true;
      }
      insideBefore = front;
    }
    return false;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.SolidData = NewHit(hit.Data, hit.Aux.X, hit.Aux.Y);
  }
}
