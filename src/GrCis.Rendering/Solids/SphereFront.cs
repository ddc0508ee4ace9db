using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The unit sphere seen from the front only (glow effects). Only the first hit is reported;
/// with <see cref="shell"/> a second, exiting hit follows at <see cref="Intersection.SHELL_THICKNESS"/>
/// so that the object behaves as a thin closed shell in CSG. Texture coordinates u = v =
/// distance of the hit from the centre as projected along the ray (0 in the middle, 1 at the rim).
/// </summary>
public class SphereFront : Sphere
{
  /// <summary>Report the thin shell's exit too.</summary>
  public bool shell;

  /// <summary>The unit sphere seen from the front.</summary>
  /// <param name="shell">True (default): a second, exiting hit follows the front one, so the sphere acts as a thin closed shell in CSG.</param>
  public SphereFront(bool shell = true) => this.shell = shell;

  /// <summary>
  /// The front (entering) hit of the line with the unit sphere, and with <see cref="shell"/> the exit
  /// <see cref="Intersection.SHELL_THICKNESS"/> behind it; null on a miss. The far side of the sphere is never reported.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Roots(p0, p1, out double t0, out _))
      return null;

    var result = new LinkedList<Intersection>();
    Vector3d c0 = p0 + t0 * p1;
    result.AddLast(new Intersection(this) { T = t0, Enter = true, Front = true, CoordLocal = c0, NormalLocal = c0, SolidData = p1 });
    if (shell)
    {
      double t = t0 + Intersection.SHELL_THICKNESS;
      Vector3d c = p0 + t * p1;
      result.AddLast(new Intersection(this) { T = t, Enter = false, Front = false, CoordLocal = c, NormalLocal = c, SolidData = p1 });
    }
    return result;
  }

  // ---------------------------------------------------------------- fast path (same Roots, same records)

  /// <inheritdoc/>
  public override bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(SphereFront));

  /// <summary>Without the shell the list ends inside; the shell's exit may lie just outside the box: open.</summary>
  public override bool IsClosed => false;

  /// <inheritdoc/>
  public override bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Roots(p0, p1, out double t0, out _))
      return false;
    return SolidSupport.FrontOrShell(t0, p0, p1, len2, shell, out hit, out insideBefore);
  }

  /// <inheritdoc/>
  public override int MaxRecords => 2;

  /// <inheritdoc/>
  public override int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Roots(p0, p1, out double t0, out _))
      return 0;
    return SolidSupport.FrontAndShell(t0, p0, p1, shell, dst);
  }

  /// <inheritdoc/>
  public override void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = hit.CoordLocal;
    target.SolidData = hit.Aux;
  }

  /// <summary>
  /// Completes as <see cref="Sphere"/> does, then replaces the texture coordinates by u = v = the sine of the
  /// angle between the ray and the hit point's direction from the centre (0 in the middle, 1 at the rim).
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    base.CompleteIntersection(inter);
    Vector3d p = inter.CoordLocal;
    if (inter.SolidData is Vector3d direction && direction.LengthSquared > 0.0 && p.LengthSquared > 0.0)
    {
      double cosa = Vector3d.Dot(direction.Normalized(), p.Normalized());
      double sina = Math.Sqrt(Math.Max(0.0, 1.0 - cosa * cosa));
      inter.TextureCoord = new Vector2d(sina, sina);
    }
    else
    {
      double r = Math.Max(1.0e-12, Math.Sqrt(p.X * p.X + p.Y * p.Y));
      inter.TextureCoord = new Vector2d(p.X / r, p.Y / r);
    }
  }
}
