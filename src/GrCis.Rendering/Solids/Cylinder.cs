using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The cylinder of unit radius about the local z axis: an infinite tube, or a solid capped
/// at z = <see cref="ZMin"/> and z = <see cref="ZMax"/>. Texture coordinates: u = longitude
/// about z in [0, 1) on the side and 0 on the caps, v = local z.
/// </summary>
public class Cylinder : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>Lower cap (−∞: none).</summary>
  public double ZMin { get; set; }

  /// <summary>Upper cap (+∞: none).</summary>
  public double ZMax { get; set; }

  /// <summary>The infinite tube.</summary>
  public Cylinder()
    : this(double.NegativeInfinity, double.PositiveInfinity)
  {
  }

  /// <summary>The cylinder between two caps.</summary>
  public Cylinder(double zMin, double zMax)
  {
    ZMin = zMin;
    ZMax = zMax;
  }

  /// <summary>Where the ray meets the solid: entry and exit, each on the side (cap = 0) or a cap (∓1).</summary>
  protected bool Span(Vector3d p0, Vector3d p1, out double tIn, out int capIn, out double tOut, out int capOut)
  {
    tIn = tOut = 0.0;
    capIn = capOut = 0;
    double a = p1.X * p1.X + p1.Y * p1.Y;
    double c = p0.X * p0.X + p0.Y * p0.Y - 1.0;

    if (a == 0.0)
    {
      // Parallel to the axis: inside the tube it can only cross the caps.
      if (c >= 0.0 || p1.Z == 0.0)
        return false;
      double tLow = (ZMin - p0.Z) / p1.Z, tHigh = (ZMax - p0.Z) / p1.Z;
      capIn = p1.Z > 0.0 ? -1 : 1;
      tIn = p1.Z > 0.0 ? tLow : tHigh;
      tOut = p1.Z > 0.0 ? tHigh : tLow;
      capOut = -capIn;
      return !double.IsInfinity(tIn) && !double.IsInfinity(tOut);
    }

    // Side: a t² + 2 h t + c = 0, discriminant from the closest approach to the axis.
    double h = p0.X * p1.X + p0.Y * p1.Y;
    double cx = p0.X - h / a * p1.X, cy = p0.Y - h / a * p1.Y;
    double disc = a * (1.0 - (cx * cx + cy * cy));
    if (!SolidSupport.SolveQuadratic(a, h, c, disc, out double t1, out double t2))
      return false;

    double z1 = p0.Z + t1 * p1.Z, z2 = p0.Z + t2 * p1.Z;
    double zLow = Math.Min(z1, z2), zHigh = Math.Max(z1, z2);
    if (zLow >= ZMax || zHigh <= ZMin)
      return false;

    // A cap lying strictly between the two side hits replaces one of them.
    bool base1 = ZMin > zLow && ZMin < zHigh;
    bool base2 = ZMax > zLow && ZMax < zHigh;

    if (base1 && p1.Z > 0.0)
    {
      tIn = (ZMin - p0.Z) / p1.Z;
      capIn = -1;
    }
    else if (base2 && p1.Z < 0.0)
    {
      tIn = (ZMax - p0.Z) / p1.Z;
      capIn = 1;
    }
    else
      tIn = t1;

    if (base1 && p1.Z < 0.0)
    {
      tOut = (ZMin - p0.Z) / p1.Z;
      capOut = -1;
    }
    else if (base2 && p1.Z > 0.0)
    {
      tOut = (ZMax - p0.Z) / p1.Z;
      capOut = 1;
    }
    else
      tOut = t2;
    return true;
  }

  /// <summary>
  /// The entry and the exit of the line <c>p0 + t * p1</c> (local coordinates), each on the side or on a cap,
  /// sorted by <see cref="Intersection.T"/>; null on a miss.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Span(p0, p1, out double tIn, out int capIn, out double tOut, out int capOut))
      return null;

    var result = new LinkedList<Intersection>();
    result.AddLast(Record(p0, p1, tIn, capIn, true));
    result.AddLast(Record(p0, p1, tOut, capOut, false));
    return result;
  }

  Intersection Record(Vector3d p0, Vector3d p1, double t, int cap, bool enter)
  {
    Vector3d p = RecordPoint(p0, p1, t, cap);
    return new Intersection(this)
    {
      T = t,
      Enter = enter,
      Front = enter,
      CoordLocal = p,
      NormalLocal = RecordNormal(p, cap),
    };
  }

  Vector3d RecordPoint(in Vector3d p0, in Vector3d p1, double t, int cap)
  {
    Vector3d p = p0 + t * p1;
    if (cap != 0)
      p.Z = cap < 0 ? ZMin : ZMax;   // exactly on the cap plane
    return p;
  }

  static Vector3d RecordNormal(in Vector3d p, int cap) =>
    cap == 0 ? new Vector3d(p.X, p.Y, 0.0) : new Vector3d(0.0, 0.0, cap);

  // ---------------------------------------------------------------- fast path (same Span, same records)

  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(Cylinder));

  /// <summary>Capped cylinders are closed; an open-ended tube's records may lie beyond any box.</summary>
  public virtual bool IsClosed => double.IsFinite(ZMin) && double.IsFinite(ZMax);

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Span(p0, p1, out double tIn, out int capIn, out double tOut, out int capOut) ||
        !SolidSupport.FirstOfPair(tIn, tOut, len2, out bool second, out insideBefore))
      return false;
    hit.T = second ? tOut : tIn;
    hit.Data = second ? capOut : capIn;
    hit.CoordLocal = RecordPoint(p0, p1, hit.T, hit.Data);
    hit.Enter = hit.Front = !second;
    return true;
  }

  /// <inheritdoc/>
  public virtual int MaxRecords => 2;

  /// <inheritdoc/>
  public virtual int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Span(p0, p1, out double tIn, out int capIn, out double tOut, out int capOut))
      return 0;
    dst[0] = new SolidRecord { T = tIn, CoordLocal = RecordPoint(p0, p1, tIn, capIn), Data = capIn, Enter = true, Front = true };
    dst[1] = new SolidRecord { T = tOut, CoordLocal = RecordPoint(p0, p1, tOut, capOut), Data = capOut };
    return 2;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = RecordNormal(hit.CoordLocal, hit.Data);
  }

  /// <summary>
  /// Sets the texture coordinates (see <see cref="Cylinder"/>), the normal (radial on the side, ±z on a cap) and
  /// the tangents (around the axis and along z on the side, x and y on a cap).
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    Vector3d p = inter.CoordLocal;
    if (inter.NormalLocal.Z != 0.0)
    {
      inter.TextureCoord = new Vector2d(0.0, p.Z);
      SolidSupport.SetWorldFrame(inter, inter.NormalLocal, Vector3d.UnitX, Vector3d.UnitY);
    }
    else
    {
      inter.TextureCoord = new Vector2d(SolidSupport.Longitude(p.X, p.Y), p.Z);
      SolidSupport.SetWorldFrame(inter, new Vector3d(p.X, p.Y, 0.0), new Vector3d(-p.Y, p.X, 0.0), Vector3d.UnitZ);
    }
  }

  /// <summary>The box [−1, 1] × [−1, 1] × [<see cref="ZMin"/>, <see cref="ZMax"/>]; a missing cap gives ±<see cref="DefaultSceneNode.INFINITY_PLACEHOLDER"/>.</summary>
  /// <param name="corner1">The minimal corner.</param>
  /// <param name="corner2">The maximal corner.</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = new Vector3d(-1.0, -1.0, SolidSupport.Finite(ZMin));
    corner2 = new Vector3d(1.0, 1.0, SolidSupport.Finite(ZMax));
  }
}
