using Scene3D;
using System;
using System.Collections.Generic;
using System.Threading;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// A triangle mesh (<see cref="SceneBrep"/>) as a solid. Every crossing of the line with a
/// triangle is reported, sorted by T; Enter = Front = the ray runs against the face's
/// geometric normal (b − a) × (c − a), so a closed, consistently oriented mesh works in CSG.
/// With <see cref="Smooth"/> and vertex normals the shading normal is interpolated; texture
/// coordinates are interpolated when the mesh has them (GrCis leaves them zero). The search
/// structure (<see cref="MeshBvh"/>) is built on first use; change the mesh before rendering.
/// </summary>
public class TriangleMesh : DefaultSceneNode, ISolid, IRecordSolid, IAnyHitSolid, ISurfaceSolid
{
  /// <summary>The mesh (GrCis keeps it reachable for subclasses).</summary>
  protected SceneBrep mesh;

  MeshBvh? bvh;
  MeshTriangles? triangles;

  /// <summary>Treat the surface as a thin double-sided shell: each crossing adds an exit just behind it.</summary>
  public bool ShellMode { get; set; }

  /// <summary>Interpolate vertex normals (when the mesh has them).</summary>
  public bool Smooth { get; set; }

  /// <summary>A solid of the triangles of <paramref name="m"/>, smooth-shaded (<see cref="Smooth"/>), not in shell mode. The mesh is kept, not copied.</summary>
  /// <param name="m">The mesh, in the node's local coordinates.</param>
  /// <exception cref="ArgumentNullException"><paramref name="m"/> is null.</exception>
  public TriangleMesh(SceneBrep m)
  {
    ArgumentNullException.ThrowIfNull(m);
    mesh = m;
    ShellMode = false;
    Smooth = true;
  }

  /// <summary>The mesh as given (the tessellation copies its triangles).</summary>
  internal SceneBrep Mesh => mesh;

  /// <summary>Distance behind a shell-mode crossing where the shell is left (ray parameter units, as GrCis).</summary>
  public const double SHELL_OFFSET = 1.0e-4;

  internal MeshBvh Bvh
  {
    get
    {
      MeshBvh? b = Volatile.Read(ref bvh);
      if (b != null)
        return b;
      Interlocked.CompareExchange(ref bvh, new MeshBvh(mesh), null);
      return bvh!;
    }
  }

  /// <summary>The flat triangle list the faithful path searches (built on first use).</summary>
  internal MeshTriangles Triangles
  {
    get
    {
      MeshTriangles? t = Volatile.Read(ref triangles);
      if (t != null)
        return t;
      Interlocked.CompareExchange(ref triangles, new MeshTriangles(mesh), null);
      return triangles!;
    }
  }

  /// <summary>Whether the BVH has been built (the faithful path never builds it).</summary>
  internal bool HasBvh => Volatile.Read(ref bvh) != null;

  /// <summary>The crossings a query collects, per worker (one query at a time per worker).</summary>
  static readonly Execution.WorkerSlot<List<MeshHit>> meshHits = new(() => new List<MeshHit>(16));

  /// <summary>
  /// Every crossing of the line <c>p0 + t * p1</c> (local coordinates) with a triangle, sorted by <see cref="Intersection.T"/>
  /// (one record for a crossing through a shared edge or vertex); in <see cref="ShellMode"/> each crossing is followed by
  /// an exit <see cref="SHELL_OFFSET"/> behind it. Null when there is none.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    Execution.WorkerContext context = Execution.WorkerContext.Current;
    List<MeshHit> hits = context.Get(meshHits);
    hits.Clear();
    double eps;
    if (ExhaustiveSearch.Active)
    {
      // --accel none: every triangle, as GrCis searched it.
      Triangles.IntersectAll(p0, p1, hits);
      eps = hits.Count > 1 ? DuplicateTolerance(Triangles.Extent, p1) : 0.0;
    }
    else
    {
      MeshBvh b = Bvh;
      b.IntersectAll(p0, p1, hits);
      eps = hits.Count > 1 ? DuplicateTolerance(b.Extent, p1) : 0.0;
    }
    if (hits.Count == 0)
      return null;
    if (hits.Count > 1)
      hits.Sort(static (x, y) => x.T != y.T ? x.T.CompareTo(y.T) : x.Triangle.CompareTo(y.Triangle));   // ties: a fixed order

    // A crossing through a shared edge or vertex is found in each incident triangle: keep one.
    var result = new LinkedList<Intersection>();
    for (int i = 0; i < hits.Count; i++)
    {
      MeshHit h = hits[i];
      if (i > 0 && h.Front == hits[i - 1].Front && h.T - hits[i - 1].T <= eps)
        continue;
      Vector3d p = p0 + h.T * p1;
      var data = new HitData(h.Triangle, h.U, h.V);
      if (ShellMode)
      {
        // A thin slab: entered here, left just behind; with Front kept, Complete() turns the
        // normal towards the ray on entry and along it on exit, whichever side was hit.
        result.AddLast(new Intersection(this) { T = h.T, Enter = true, Front = h.Front, CoordLocal = p, SolidData = data });
        result.AddLast(new Intersection(this) { T = h.T + SHELL_OFFSET, Enter = false, Front = h.Front, CoordLocal = p0 + (h.T + SHELL_OFFSET) * p1, SolidData = data });
      }
      else
        result.AddLast(new Intersection(this) { T = h.T, Enter = h.Front, Front = h.Front, CoordLocal = p, SolidData = data });
    }
    return result;
  }

  static double DuplicateTolerance(double extent, in Vector3d p1) => 1e-10 * Math.Max(extent, 1e-300) / p1.Length;

  // ---------------------------------------------------------------- fast path (same triangle test, same list)

  /// <summary>Shell mode lists overlapping entry/exit pairs: answered through the list API.</summary>
  public virtual bool RecordsMatchIntersect => !ShellMode && Accel.SubclassCheck.KeepsGeometry(this, typeof(TriangleMesh));

  /// <summary>An open mesh's list may start "inside" (a back face first): tested for every ray.</summary>
  public virtual bool IsClosed => false;

  /// <summary>
  /// One allocation-free BVH walk for two answers: the first accepted hit in list order, and the last rejected one
  /// (its Enter is the CSG state before the first accepted record; duplicates dropped by
  /// <see cref="Intersect"/> share their predecessor's Enter). In the rare case that the list would drop
  /// the first accepted hit as a duplicate of a rejected one, the list itself answers.
  /// </summary>
  public virtual bool IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    MeshBvh b = Bvh;
    b.NearestBoth(p0, p1, len2, out bool hasFirst, out MeshHit first, out bool hasLast, out MeshHit last);
    return First(b, p0, p1, len2, hasLast, last, hasFirst, first, out hit, out insideBefore);
  }

  /// <summary>
  /// The shadow query's form of <see cref="IntersectFirst"/> (the prepared scene decides when to ask it):
  /// when the list is outside just before the first accepted record (the last rejected hit is a back face), any accepted
  /// front-face hit with T ≤ <paramref name="tMax"/> may answer instead of the first one, and the walk stops there; with
  /// none, there is no record up to <paramref name="tMax"/> that changes the list's state, and none is reported (an
  /// accepted back-face hit is reported as the first record, an exit, so the caller falls back to the list). Otherwise
  /// the answer is <see cref="IntersectFirst"/>'s.
  /// </summary>
  bool IAnyHitSolid.IntersectAny(in Vector3d p0, in Vector3d p1, double len2, double tMax, out SolidRecord hit, out bool insideBefore)
  {
    MeshBvh b = Bvh;
    bool hasLast = b.Nearest(p0, p1, len2, false, out MeshHit last);
    if (!hasLast || last.Front)
    {
      bool hasFirst = b.Nearest(p0, p1, len2, true, out MeshHit first);
      return First(b, p0, p1, len2, hasLast, last, hasFirst, first, out hit, out insideBefore);
    }
    insideBefore = false;
    hit = default;
    if (!b.Any(p0, p1, len2, 0.0, tMax, true, out MeshHit any, out _, out bool onlyBack))
    {
      if (!onlyBack)
        return false;
      hit.Enter = hit.Front = false;   // an exit while outside: irregular, the list decides
      return true;
    }
    hit.T = any.T;
    hit.CoordLocal = p0 + any.T * p1;
    hit.Data = any.Triangle;
    hit.Aux = new Vector3d(any.U, any.V, 0.0);
    hit.Enter = hit.Front = true;
    return true;
  }

  /// <summary>
  /// The first accepted hit alone (one walk, ahead of the origin only, pruned at <paramref name="tMax"/>): the state before
  /// it is not asked for, and the last rejected hit can change the record only when it is the first accepted hit's
  /// duplicate (<see cref="First"/>), which needs the first accepted hit within the duplicate tolerance of the rejected
  /// hits' limit. Only then does the full query answer.
  /// </summary>
  bool IAnyHitSolid.FirstRecord(in Vector3d p0, in Vector3d p1, double len2, double tMax, out SolidRecord hit)
  {
    MeshBvh b = Bvh;
    hit = default;
    if (!b.Nearest(p0, p1, len2, true, out MeshHit first, tMax))
      return false;
    if (!(first.T > Zone(b, p1, len2)))
      return IntersectFirst(p0, p1, len2, out hit, out _) && hit.T <= tMax;
    Record(first, p0, p1, out hit);
    return true;
  }

  /// <summary>
  /// The zone (0, Z] where a duplicate can hide the first accepted hit: one beyond Z is the list's first record. Its
  /// predecessor in the list's order (T, then triangle) is rejected (acceptance grows with T), so it has T ≤ the rejected
  /// hits' limit, and the hit is more than the duplicate tolerance behind it; the margin covers the rounding of
  /// <see cref="First"/>'s difference first.T − last.T.
  /// </summary>
  internal static double Zone(MeshBvh b, in Vector3d p1, double len2) => (MeshBvh.RejectLimit(len2) + DuplicateTolerance(b.Extent, p1)) * (1.0 + 1e-9);

  /// <summary>
  /// Whether <see cref="IAnyHitSolid.FirstRecord"/>'s record exists and is not far (<see cref="PreparedScene.NotFar"/>;
  /// none beyond <paramref name="tMax"/> is), answered by one early-exit walk in any order instead of the ordered search
  /// (<see cref="MeshBvh.Any"/> with the zone (0, Z] of <see cref="Zone"/>):
  /// <list type="bullet">
  /// <item>It finds an accepted hit H with T in (Z, tMax] and no accepted hit in (0, Z]: the first accepted hit F then has
  /// T_F &gt; Z, so it is the record, and T_F ≤ T_H (F is first). When H is not far, neither is F (NotFar is monotone in
  /// T: t − 1, its square and the product with len2 round monotonely): blocked.</item>
  /// <item>It finds no accepted hit in (0, tMax]: the record, an accepted hit, is beyond tMax or absent: not blocked.</item>
  /// <item>Otherwise (an accepted hit in the zone, where duplicates may chain and drop it, or H far, in the bound's slack,
  /// or a zone reaching tMax): the ordered search decides.</item>
  /// </list>
  /// </summary>
  bool IAnyHitSolid.Occluded(in Vector3d p0, in Vector3d p1, double len2, double tMax)
  {
    MeshBvh b = Bvh;
    double zone = Zone(b, p1, len2);
    if (zone < tMax)
    {
      if (b.Any(p0, p1, len2, zone, tMax, false, out MeshHit any, out bool inZone, out _))
      {
        if (PreparedScene.NotFar(any.T, len2))
          return true;
      }
      else if (!inZone)
        return false;
    }
    return ((IAnyHitSolid)this).FirstRecord(p0, p1, len2, tMax, out SolidRecord hit) && PreparedScene.NotFar(hit.T, len2);
  }

  /// <summary>The record of an accepted hit, as the list lists it.</summary>
  static void Record(in MeshHit h, in Vector3d p0, in Vector3d p1, out SolidRecord hit)
  {
    hit = default;
    hit.T = h.T;
    hit.CoordLocal = p0 + h.T * p1;
    hit.Data = h.Triangle;
    hit.Aux = new Vector3d(h.U, h.V, 0.0);
    hit.Enter = hit.Front = h.Front;
  }

  /// <summary>The record of the first accepted hit and the state before it, from the last rejected hit.</summary>
  bool First(MeshBvh b, in Vector3d p0, in Vector3d p1, double len2, bool hasLast, in MeshHit last, bool hasFirst, in MeshHit first,
             out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = hasLast ? last.Front : hasFirst && !first.Front;
    if (!hasFirst)
      return false;
    if (hasLast && last.Front == first.Front && first.T - last.T <= DuplicateTolerance(b.Extent, p1))
      return FirstFromList(p0, p1, len2, out hit, out insideBefore);
    Record(first, p0, p1, out hit);
    return true;
  }

  bool FirstFromList(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    LinkedList<Intersection>? list = Intersect(p0, p1);
    if (list == null || list.First == null)
      return false;
    insideBefore = !list.First.Value.Enter;
    foreach (Intersection i in list)
    {
      if (SolidSupport.Accepted(i.T, len2))
      {
        var d = (HitData)i.SolidData!;
        hit = new SolidRecord { T = i.T, CoordLocal = i.CoordLocal, Data = d.Face, Aux = new Vector3d(d.U, d.V, 0.0), Enter = i.Enter, Front = i.Front };
        return true;
      }
      insideBefore = i.Enter;
    }
    return false;
  }

  /// <inheritdoc/>
  public virtual void InitIntersection(in SolidRecord hit, Intersection target)
  {
    target.SetRecord(hit);
    target.SolidData = new HitData(hit.Data, hit.Aux.X, hit.Aux.Y);
  }

  /// <summary>
  /// Sets the normal (the face's, or with <see cref="Smooth"/> the interpolated vertex normal), the texture coordinates
  /// (interpolated when the mesh has them, else zero) and the tangents (from the texture parametrisation when possible).
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    if (inter.SolidData is not HitData d)
    {
      SolidSupport.SetWorldFrame(inter, Vector3d.UnitZ);
      return;
    }
    Vector3d normal = ShadingNormal(d, out Vector3d a, out Vector3d b, out Vector3d c);
    if (mesh.TxtCoords > 0)
    {
      inter.TextureCoord = TextureCoordAt(d, out Vector2 ta, out Vector2 tb, out Vector2 tc);

      // Tangents from the texture parametrisation (dP/du, dP/dv), when it is not degenerate.
      double du1 = tb.X - ta.X, dv1 = tb.Y - ta.Y, du2 = tc.X - ta.X, dv2 = tc.Y - ta.Y;
      double det = du1 * dv2 - du2 * dv1;
      if (det != 0.0)
      {
        Vector3d e1 = b - a, e2 = c - a;
        Vector3d tu = (dv2 * e1 - dv1 * e2) / det;
        Vector3d tv = (du1 * e2 - du2 * e1) / det;
        SolidSupport.SetWorldFrame(inter, normal, tu, tv);
        return;
      }
    }
    else
      inter.TextureCoord = Vector2d.Zero;
    SolidSupport.SetWorldFrame(inter, normal);
  }

  /// <summary>
  /// The surface part of <see cref="CompleteIntersection"/> (<see cref="ISurfaceSolid"/>): the normal, local and
  /// world, and the texture coordinates, with the same arithmetic, so the same bits; no tangents. False, with nothing
  /// written, when the world normal is within GrCis's zero length (|n|² ≤ 1e-24: a tiny or degenerate triangle), which
  /// the full completion replaces by the tangents' cross product.
  /// </summary>
  bool ISurfaceSolid.CompleteSurface(Intersection inter, in Matrix4d worldToLocal)
  {
    if (inter.SolidData is not HitData d)
      return false;
    Vector3d normal;
    MeshBvh? b = Volatile.Read(ref bvh);
    if (b != null && !(Smooth && mesh.Normals > 0))
    {
      // The face normal from the leaf block the query has just read: the same vertices, so the same bits as ShadingNormal.
      b.Vertices(d.Face, out Vector3d va, out Vector3d vb, out Vector3d vc);
      normal = Vector3d.Cross(vb - va, vc - va);
    }
    else
      normal = ShadingNormal(d, out _, out _, out _);
    Vector3d world = Vector3d.TransformNormalInverse(normal, worldToLocal);
    if (world.LengthSquared <= 1.0e-24)
      return false;
    inter.TextureCoord = mesh.TxtCoords > 0 ? TextureCoordAt(d, out _, out _, out _) : Vector2d.Zero;
    inter.NormalLocal = normal;
    inter.Normal = world;
    return true;
  }

  /// <summary>The shading normal at a hit: the face's, or with <see cref="Smooth"/> the vertex normals interpolated; and the triangle's corners.</summary>
  Vector3d ShadingNormal(HitData d, out Vector3d a, out Vector3d b, out Vector3d c)
  {
    mesh.GetTriangleVertices(d.Face, out int ia, out int ib, out int ic);
    a = mesh.GetVertex(ia);
    b = mesh.GetVertex(ib);
    c = mesh.GetVertex(ic);
    Vector3d normal = Vector3d.Cross(b - a, c - a);
    if (Smooth && mesh.Normals > 0)
    {
      double w = 1.0 - d.U - d.V;
      Vector3d n = w * (Vector3d)mesh.GetNormal(ia) + d.U * (Vector3d)mesh.GetNormal(ib) + d.V * (Vector3d)mesh.GetNormal(ic);
      if (n.LengthSquared > 0.0)
        normal = n;
    }
    return normal;
  }

  /// <summary>The texture coordinates at a hit, interpolated from the corners' (<paramref name="ta"/>, <paramref name="tb"/>, <paramref name="tc"/>).</summary>
  Vector2d TextureCoordAt(HitData d, out Vector2 ta, out Vector2 tb, out Vector2 tc)
  {
    mesh.GetTriangleVertices(d.Face, out int ia, out int ib, out int ic);
    ta = mesh.GetTxtCoord(ia);
    tb = mesh.GetTxtCoord(ib);
    tc = mesh.GetTxtCoord(ic);
    double w = 1.0 - d.U - d.V;
    return new Vector2d(w * ta.X + d.U * tb.X + d.V * tc.X, w * ta.Y + d.U * tb.Y + d.V * tc.Y);
  }

  /// <summary>The box of all the mesh's vertices (a point at the origin for an empty mesh).</summary>
  /// <param name="corner1">The minimal corner.</param>
  /// <param name="corner2">The maximal corner.</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    if (mesh.Vertices == 0)
    {
      corner1 = corner2 = Vector3d.Zero;
      return;
    }
    Vector3d min = Vector3d.PositiveInfinity, max = Vector3d.NegativeInfinity;
    for (int i = 0; i < mesh.Vertices; i++)
    {
      Vector3d p = mesh.GetVertex(i);
      min = Vector3d.ComponentMin(min, p);
      max = Vector3d.ComponentMax(max, p);
    }
    corner1 = min;
    corner2 = max;
  }

  /// <summary>The triangle and barycentrics of a hit (p = (1 − U − V)·a + U·b + V·c).</summary>
  sealed class HitData
  {
    public readonly int Face;
    public readonly double U, V;

    public HitData(int face, double u, double v)
    {
      Face = face;
      U = u;
      V = v;
    }
  }
}
