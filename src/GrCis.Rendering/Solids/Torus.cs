using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// Torus about the local z axis: the tube of radius <see cref="smallRadius"/> around the circle
/// of radius <see cref="bigRadius"/> in the xy plane, i.e. the solid where
/// (|p|² + R² − r²)² − 4R²(x² + y²) &lt; 0 (for a spindle torus, R &lt; r, the inner lemon is outside).
/// The ray is first clipped by the bounding sphere (radius R + r) and the quartic is written
/// about the ray's point closest to the centre, with a unit direction, so its coefficients
/// stay of the torus's size wherever the ray starts; roots are isolated and refined on that
/// bounded interval (<see cref="QuarticRoots"/>). All hits are returned, sorted, negative T included.
/// Texture coordinates: u = longitude about z, v = angle around the tube / 2π (+0.5).
/// </summary>
public class Torus : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>Distance of the tube's centre line from the axis (R).</summary>
  public double bigRadius = 1.0;

  /// <summary>Radius of the tube (r).</summary>
  public double smallRadius = 0.5;

  /// <summary>
  /// Whether a ray that starts on this torus's surface (a shadow, reflected or refracted ray) may hit
  /// this torus again. GrCis's torus solver loses exactly those roots, so old scenes were lit as if a
  /// torus never shadowed or mirrored itself; false (the default) keeps that look. Set true for
  /// the physically right image: self-shadowing and self-reflection, e.g. inside the hole.
  /// </summary>
  public bool SelfHits;

  /// <summary>A sphere around the torus (R + r), for subclasses that test it first as GrCis's torus did.</summary>
  protected BoundingSphere boundingSphere;

  /// <summary>A torus about the local z axis, e.g. <c>new Torus(1.0, 0.5)</c>; local units.</summary>
  /// <param name="bigRadius">Distance of the tube's centre line from the axis (R).</param>
  /// <param name="smallRadius">Radius of the tube (r).</param>
  public Torus(double bigRadius, double smallRadius)
  {
    this.bigRadius = bigRadius;
    this.smallRadius = smallRadius;
    boundingSphere = new BoundingSphere(bigRadius + smallRadius);
  }

  /// <summary>
  /// All points (up to four) where the line <c>p0 + t * p1</c> (local coordinates) crosses the torus, sorted by
  /// <see cref="Intersection.T"/>, negative T included; null on a miss, and (unless <see cref="SelfHits"/>)
  /// when the ray starts on the torus's surface.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    if (!SelfHits && StartsOnSurface(p0))
      return null;
    Span<double> u = stackalloc double[4];
    Span<bool> enter = stackalloc bool[4];
    int n = Solve(p0, p1, u, enter, out Vector3d center, out Vector3d dir, out double sMid, out double length);
    if (n == 0)
      return null;

    var result = new LinkedList<Intersection>();
    for (int i = 0; i < n; i++)
    {
      result.AddLast(new Intersection(this)
      {
        T = (sMid + u[i]) / length,
        Enter = enter[i],
        Front = enter[i],
        CoordLocal = center + u[i] * dir,
      });
    }
    return result;
  }

  // ---------------------------------------------------------------- fast path (same Solve, same records)

  /// <inheritdoc/>
  public virtual bool RecordsMatchIntersect => Accel.SubclassCheck.KeepsGeometry(this, typeof(Torus));

  /// <summary>Roots lie inside the (enlarged) bounding sphere and alternate from an entry: closed.</summary>
  public virtual bool IsClosed => true;

  /// <inheritdoc/>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (!SelfHits && StartsOnSurface(p0))
      return false;
    Span<double> u = stackalloc double[4];
    Span<bool> enter = stackalloc bool[4];
    int n = Solve(p0, p1, u, enter, out Vector3d center, out Vector3d dir, out double sMid, out double length);
    if (n == 0)
      return false;
    insideBefore = !enter[0];
    for (int i = 0; i < n; i++)
    {
      double t = (sMid + u[i]) / length;
      if (SolidSupport.Accepted(t, len2))
      {
        hit.T = t;
        hit.CoordLocal = center + u[i] * dir;
        hit.Enter = hit.Front = enter[i];
        return true;
      }
      insideBefore = enter[i];
    }
    return false;
  }

  /// <inheritdoc/>
  public virtual int MaxRecords => 4;

  /// <inheritdoc/>
  public virtual int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> dst)
  {
    if (!SelfHits && StartsOnSurface(p0))
      return 0;
    Span<double> u = stackalloc double[4];
    Span<bool> enter = stackalloc bool[4];
    int n = Solve(p0, p1, u, enter, out Vector3d center, out Vector3d dir, out double sMid, out double length);
    for (int i = 0; i < n; i++)
      dst[i] = new SolidRecord { T = (sMid + u[i]) / length, CoordLocal = center + u[i] * dir, Enter = enter[i], Front = enter[i] };
    return n;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
  }

  /// <summary>True when <paramref name="p0"/> lies on the surface (within rounding of a computed hit point).</summary>
  internal bool StartsOnSurface(Vector3d p0)
  {
    // Distance to the tube about the nearer circle point, and about the opposite one: a spindle
    // torus's inner lemon belongs to the tube of the far side.
    double R = Math.Abs(bigRadius), r = Math.Abs(smallRadius);
    double rho = Math.Sqrt(p0.X * p0.X + p0.Y * p0.Y);
    double z2 = p0.Z * p0.Z;
    double near = Math.Sqrt((rho - R) * (rho - R) + z2) - r;
    double far = Math.Sqrt((rho + R) * (rho + R) + z2) - r;
    double tolerance = 1.0e-7 * (R + r);
    return Math.Abs(near) <= tolerance || Math.Abs(far) <= tolerance;
  }

  /// <summary>
  /// Roots along the ray as offsets <paramref name="u"/> (distance units) from the ray's point
  /// closest to the origin (<paramref name="center"/>, at distance <paramref name="sMid"/> along the unit
  /// <paramref name="dir"/>); the ray parameter is <c>(sMid + u) / length</c>.
  /// </summary>
  internal int Solve(Vector3d p0, Vector3d p1, Span<double> u, Span<bool> enter,
                     out Vector3d center, out Vector3d dir, out double sMid, out double length)
  {
    center = dir = Vector3d.Zero;
    sMid = 0.0;
    length = p1.Length;
    double R = Math.Abs(bigRadius), r = Math.Abs(smallRadius);
    if (!(length > 0.0) || !(r > 0.0) || double.IsInfinity(length))
      return 0;

    // Clip by a slightly enlarged bounding sphere (f > 0 on it).
    dir = p1 / length;
    sMid = -Vector3d.Dot(p0, dir);
    center = p0 + sMid * dir;
    double rb = (R + r) * (1.0 + 1.0e-9);
    double h2 = rb * rb - center.LengthSquared;
    if (!(h2 > 0.0))
      return 0;
    double h = Math.Sqrt(h2);

    // Quartic in u about the centre point: (|c + u d|² − R² − r²)² + 4R²((cz + u dz)² − r²).
    double od = Vector3d.Dot(center, dir);   // ≈ 0, kept for exactness
    double k = center.LengthSquared - R * R - r * r;
    double r2x4 = 4.0 * R * R;
    double c3 = 4.0 * od;
    double c2 = 4.0 * od * od + 2.0 * k + r2x4 * dir.Z * dir.Z;
    double c1 = 4.0 * od * k + 2.0 * r2x4 * center.Z * dir.Z;
    double c0 = k * k + r2x4 * (center.Z * center.Z - r * r);
    return QuarticRoots.Solve(c3, c2, c1, c0, -h, h, u, enter);
  }

  /// <summary>Sets the texture coordinates (see <see cref="Torus"/>), the normal (the gradient of the torus equation) and the tangents (around the axis, around the tube).</summary>
  public override void CompleteIntersection(Intersection inter)
  {
    Vector3d p = inter.CoordLocal;
    double R = Math.Abs(bigRadius), r = Math.Abs(smallRadius);
    double rho = Math.Sqrt(p.X * p.X + p.Y * p.Y);
    if (rho == 0.0)
    {
      // On the axis (spindle torus apex): the axis direction.
      inter.TextureCoord = new Vector2d(0.0, p.Z >= 0.0 ? 0.5 : 1.0);
      SolidSupport.SetWorldFrame(inter, new Vector3d(0.0, 0.0, p.Z >= 0.0 ? 1.0 : -1.0));
      return;
    }

    // f = A·B with A, B the squared distances to the tube circles at ±c minus r²; the hit lies
    // on the factor nearer to zero and the gradient of f is (other factor)·(p ∓ c).
    Vector3d c = new Vector3d(p.X, p.Y, 0.0) * (R / rho);
    double a = (rho - R) * (rho - R) + p.Z * p.Z - r * r;
    double b = (rho + R) * (rho + R) + p.Z * p.Z - r * r;
    Vector3d normal = Math.Abs(a) <= Math.Abs(b)
      ? (b >= 0.0 ? p - c : c - p)
      : (a >= 0.0 ? p + c : -(p + c));

    // Texture: around the axis, then around the tube centre (the opposite one inside a spindle's lemon).
    bool lemon = R < r && rho < R && p.Z * p.Z <= r * r - R * R;
    Vector3d w = p - (lemon ? -c : c);
    double r2 = Math.Sqrt(w.X * w.X + w.Y * w.Y);
    if (rho < R)
      r2 = -r2;
    inter.TextureCoord = new Vector2d(SolidSupport.Longitude(p.X, p.Y), Math.Atan2(r2, p.Z) / (2.0 * Math.PI) + 0.5);

    Vector3d tu = new Vector3d(-p.Y, p.X, 0.0);
    SolidSupport.SetWorldFrame(inter, normal, tu, Vector3d.Cross(tu, normal));
  }

  /// <summary>The box [−(R + r), R + r]² × [−r, r] (absolute values of the radii).</summary>
  /// <param name="corner1">The minimal corner.</param>
  /// <param name="corner2">The maximal corner.</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    double R = Math.Abs(bigRadius), r = Math.Abs(smallRadius);
    corner1 = new Vector3d(-R - r, -R - r, -r);
    corner2 = new Vector3d(R + r, R + r, r);
  }
}
