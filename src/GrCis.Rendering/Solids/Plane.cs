using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The local z = 0 plane: infinite, a rectangle, or a right triangle. One hit per ray;
/// the front side is +z (Enter = Front = the ray comes from +z). Texture coordinates:
/// (x, y) along infinite directions, normalised to [0, 1] along bounded ones; on the
/// triangle the two barycentric-like coordinates x/xMax, y/yMax.
/// </summary>
public class Plane : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>Lower bound of x.</summary>
  public double XMin { get; set; }

  /// <summary>Upper bound of x; for a triangle its reciprocal (the constraint is x·XMax + y·YMax ≤ 1).</summary>
  public double XMax { get; set; }

  /// <summary>Lower bound of y.</summary>
  public double YMin { get; set; }

  /// <summary>Upper bound of y; for a triangle its reciprocal.</summary>
  public double YMax { get; set; }

  /// <summary>Three constraints instead of four: x ≥ 0, y ≥ 0, x·XMax + y·YMax ≤ 1.</summary>
  public bool Triangle { get; set; }

  /// <summary>u = x (otherwise u = (x − XMin)·ScaleU).</summary>
  public bool CanonicU { get; set; }

  /// <summary>v = y (otherwise v = (y − YMin)·ScaleV).</summary>
  public bool CanonicV { get; set; }

  /// <summary>Scale of u when <see cref="CanonicU"/> is false: u = (x − XMin)·ScaleU; 1/(xMax − xMin) for a rectangle bounded in x, else 1.</summary>
  public double ScaleU { get; set; }

  /// <summary>Scale of v when <see cref="CanonicV"/> is false: v = (y − YMin)·ScaleV; 1/(yMax − yMin) for a rectangle bounded in y, else 1.</summary>
  public double ScaleV { get; set; }

  /// <summary>The infinite plane.</summary>
  public Plane()
    : this(double.NegativeInfinity, double.PositiveInfinity, double.NegativeInfinity, double.PositiveInfinity)
  {
  }

  /// <summary>The rectangle [xMin, xMax] × [yMin, yMax] (bounds may be infinite).</summary>
  public Plane(double xMin, double xMax, double yMin, double yMax)
  {
    XMin = xMin;
    XMax = xMax;
    YMin = yMin;
    YMax = yMax;
    Triangle = false;
    CanonicU = CanonicV = true;
    ScaleU = ScaleV = 1.0;
    if (!double.IsInfinity(xMin) && !double.IsInfinity(xMax))
    {
      CanonicU = false;
      ScaleU = 1.0 / (xMax - xMin);
    }
    if (!double.IsInfinity(yMin) && !double.IsInfinity(yMax))
    {
      CanonicV = false;
      ScaleV = 1.0 / (yMax - yMin);
    }
  }

  /// <summary>The triangle (0,0), (xMax,0), (0,yMax); a non-positive size counts as 1.</summary>
  public Plane(double xMax, double yMax)
  {
    XMin = YMin = 0.0;
    XMax = xMax < double.Epsilon ? 1.0 : 1.0 / xMax;
    YMax = yMax < double.Epsilon ? 1.0 : 1.0 / yMax;
    Triangle = CanonicU = CanonicV = true;
    ScaleU = ScaleV = 1.0;
  }

  /// <summary>
  /// The one point where the line <c>p0 + t * p1</c> (local coordinates) crosses the plane z = 0 inside the
  /// bounds; null when it misses or runs parallel. <see cref="Intersection.Enter"/> and <see cref="Intersection.Front"/>
  /// are true for a ray coming from +z.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!Hit(p0, p1, out double t, out double x, out double y))
      return null;

    bool front = p1.Z < 0.0;
    var result = new LinkedList<Intersection>();
    result.AddLast(new Intersection(this)
    {
      T = t,
      Enter = front,
      Front = front,
      CoordLocal = new Vector3d(x, y, 0.0),
      NormalLocal = Vector3d.UnitZ,
    });
    return result;
  }

  /// <summary>The one record's parameter and local (x, y); false on a miss.</summary>
  bool Hit(in Vector3d p0, in Vector3d p1, out double t, out double x, out double y)
  {
    t = x = y = 0.0;
    if (p1.Z == 0.0)
      return false;

    t = -p0.Z / p1.Z;
    x = p0.X + t * p1.X;
    y = p0.Y + t * p1.Y;
    return Inside(x, y);
  }

  // ---------------------------------------------------------------- fast path (same Hit, same record)

  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(Plane));

  /// <summary>One record (an exit from below): the list may start inside, so the plane is tested for every ray.</summary>
  public virtual bool IsClosed => false;

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore) =>
    First(p0, p1, len2, out hit, out insideBefore);

  /// <summary><see cref="IntersectFirst"/> of this class itself: the prepared query calls it directly for a member of exactly this type.</summary>
  internal bool First(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!Hit(p0, p1, out double t, out double x, out double y))
      return false;
    bool front = p1.Z < 0.0;
    if (SolidSupport.Accepted(t, len2))
    {
      insideBefore = !front;
      hit.T = t;
      hit.CoordLocal = new Vector3d(x, y, 0.0);
      hit.Enter = hit.Front = front;
      return true;
    }
    insideBefore = front;
    return false;
  }

  /// <inheritdoc/>
  public virtual int MaxRecords => 1;

  /// <inheritdoc/>
  public virtual int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!Hit(p0, p1, out double t, out double x, out double y))
      return 0;
    bool front = p1.Z < 0.0;
    dst[0] = new SolidRecord { T = t, CoordLocal = new Vector3d(x, y, 0.0), Enter = front, Front = front };
    return 1;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target) => Init(hit, target);

  /// <summary><see cref="InitIntersection"/> of this class itself (called directly, inlined, for exactly this type).</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  internal static void Init(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.NormalLocal = Vector3d.UnitZ;
  }

  bool Inside(double x, double y)
  {
    if (x < XMin || y < YMin)
      return false;
    if (Triangle)
      return x * XMax + y * YMax <= 1.0;
    return x <= XMax && y <= YMax;
  }

  /// <summary>Sets the texture coordinates (see <see cref="Plane"/>), the normal +z and the tangents x and y.</summary>
  public override void CompleteIntersection(Intersection inter)
  {
    inter.TextureCoord = TextureCoordAt(inter.CoordLocal);
    SolidSupport.SetWorldFrame(inter, Vector3d.UnitZ, Vector3d.UnitX, Vector3d.UnitY);
  }

  /// <summary>Texture coordinates of local point <paramref name="p"/>: scaled to the rectangle, or the triangle's.</summary>
  internal Vector2d TextureCoordAt(in Vector3d p) =>
    Triangle
      ? new Vector2d(p.X * XMax, p.Y * YMax)
      : new Vector2d(CanonicU ? p.X : (p.X - XMin) * ScaleU, CanonicV ? p.Y : (p.Y - YMin) * ScaleV);

  /// <summary>The part of <see cref="CompleteIntersection"/> the library's shading reads (same arithmetic): no tangents.</summary>
  internal void CompleteSurface(Intersection inter, in Matrix4d worldToLocal)
  {
    inter.TextureCoord = TextureCoordAt(inter.CoordLocal);
    inter.NormalLocal = Vector3d.UnitZ;
    inter.Normal = Vector3d.TransformNormalInverse(Vector3d.UnitZ, worldToLocal);
  }

  /// <summary>
  /// The flat box of the rectangle, [XMin, XMax] × [YMin, YMax] × [0, 0] (infinite bounds as
  /// ±<see cref="DefaultSceneNode.INFINITY_PLACEHOLDER"/>), or of the triangle.
  /// </summary>
  /// <param name="corner1">The minimal corner.</param>
  /// <param name="corner2">The maximal corner.</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    if (Triangle)
    {
      corner1 = Vector3d.Zero;
      corner2 = new Vector3d(1.0 / XMax, 1.0 / YMax, 0.0);
      return;
    }
    corner1 = new Vector3d(SolidSupport.Finite(XMin), SolidSupport.Finite(YMin), 0.0);
    corner2 = new Vector3d(SolidSupport.Finite(XMax), SolidSupport.Finite(YMax), 0.0);
  }
}
