using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The cylinder's side seen from the front only (glow effects). Rays that would enter
/// through a cap miss; otherwise only the front side hit is reported (plus, with
/// <see cref="shell"/>, a thin shell's exit). Texture coordinates u = v = distance of the hit
/// from the axis as projected along the ray.
/// </summary>
public class CylinderFront : Cylinder
{
  /// <summary>Report the thin shell's exit too.</summary>
  public bool shell;

  /// <summary>The infinite tube.</summary>
  public CylinderFront(bool shell = true)
    : base(double.NegativeInfinity, double.PositiveInfinity) => this.shell = shell;

  /// <summary>The tube between zMin and zMax.</summary>
  public CylinderFront(double zMin, double zMax, bool shell = true)
    : base(zMin, zMax) => this.shell = shell;

  /// <summary>
  /// The front (entering) hit of the line on the cylinder's side, and with <see cref="shell"/> the exit
  /// <see cref="Intersection.SHELL_THICKNESS"/> behind it; null on a miss or when the ray would enter through a cap.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Span(p0, p1, out double t, out int capIn, out _, out _) || capIn != 0)
      return null;

    var result = new LinkedList<Intersection>();
    Vector3d p = p0 + t * p1;
    result.AddLast(new Intersection(this) { T = t, Enter = true, Front = true, CoordLocal = p, NormalLocal = new Vector3d(p.X, p.Y, 0.0), SolidData = p1 });
    if (shell)
    {
      double t2 = t + Intersection.SHELL_THICKNESS;
      Vector3d q = p0 + t2 * p1;
      result.AddLast(new Intersection(this) { T = t2, Enter = false, Front = false, CoordLocal = q, NormalLocal = new Vector3d(q.X, q.Y, 0.0), SolidData = p1 });
    }
    return result;
  }

  // ---------------------------------------------------------------- fast path (same Span, same records)

  /// <inheritdoc/>
  public override bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(CylinderFront));

  /// <summary>Without the shell the list ends inside; the shell's exit may lie just outside the box: open.</summary>
  public override bool IsClosed => false;

  /// <inheritdoc/>
  public override bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Span(p0, p1, out double t, out int capIn, out _, out _) || capIn != 0)
      return false;
    return SolidSupport.FrontOrShell(t, p0, p1, len2, shell, out hit, out insideBefore);
  }

  /// <inheritdoc/>
  public override int MaxRecords => 2;

  /// <inheritdoc/>
  public override int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Span(p0, p1, out double t, out int capIn, out _, out _) || capIn != 0)
      return 0;
    return SolidSupport.FrontAndShell(t, p0, p1, shell, dst);
  }

  /// <inheritdoc/>
  public override void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = new Vector3d(hit.CoordLocal.X, hit.CoordLocal.Y, 0.0);
    target.SolidData = hit.Aux;
  }

  /// <summary>
  /// Sets the radial normal and the tangents, and texture coordinates u = v = the sine of the angle between the
  /// ray and the radial direction, both seen along the axis (0 where the ray meets the side head-on, 1 at the silhouette).
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    Vector3d p = inter.CoordLocal;
    SolidSupport.SetWorldFrame(inter, new Vector3d(p.X, p.Y, 0.0), new Vector3d(-p.Y, p.X, 0.0), Vector3d.UnitZ);
    if (inter.SolidData is Vector3d d && (d.X != 0.0 || d.Y != 0.0))
    {
      double len = Math.Sqrt(d.X * d.X + d.Y * d.Y);
      double cosa = (p.X * d.X + p.Y * d.Y) / len;
      double sina = Math.Sqrt(Math.Max(0.0, 1.0 - cosa * cosa));
      inter.TextureCoord = new Vector2d(sina, sina);
    }
    else
      inter.TextureCoord = Vector2d.Zero;
  }
}
