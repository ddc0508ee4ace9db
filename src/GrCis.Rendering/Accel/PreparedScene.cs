using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Threading;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// A scene prepared for fast ray queries (once per frame): union CSG nodes are flattened into members,
/// each member's transform chain and world matrices are computed once, and closed members are put in a
/// BVH (binned SAH). Queries allocate nothing except the <see cref="Intersection"/> of the winning hit.
/// </summary>
/// <remarks>
/// <para><b>When is a union a pure container?</b> GrCis merges a union's children left to right and keeps
/// a record only where the union's inside state changes; <see cref="Intersection.FirstIntersection"/> then
/// takes the first record with T &gt; 0 and T²|p1|² &gt; RAY_EPSILON2 ("valid"). Let every member report its
/// first valid record and its inside state just before it (<see cref="IRecordSolid.IntersectFirst"/>). If no
/// member is inside there and every member's first valid record is an entry, the union is outside until
/// the first entry, so its first valid record is the smallest first valid record over the members (ties:
/// the member first in depth-first order, as the merge keeps the left operand's record). Otherwise — the
/// ray starts inside some member (refraction rays, rays from below a plane) or a member's list is
/// irregular — the query is answered by the faithful path on the whole scene. This rule is exact.</para>
/// <para><b>Pruning.</b> A closed member (records only inside its box, list starting outside) whose box
/// lies behind the origin or beyond the best hit so far can neither win nor be inside at the origin, so
/// the BVH may skip it. Open members (planes, script solids) are tested for every ray, except a bounded plane
/// whose padded world box the ray's whole line misses: it has no record at any t. Bounded rectangles are culled four
/// at a time in world space (<see cref="RectangleCull"/>), and at most eight closed balls likewise instead of a BVH
/// (<see cref="SphereCull"/>); both skip only members whose exact test would change nothing.</para>
/// <para>The ray is taken into each member's space through the same FromParent matrices, in the same
/// order, as <see cref="CSGInnerNode.Intersect"/> does, so T and local coordinates are bit-identical.
/// Shadow rays use the same query bounded by the light (<see cref="Intersection.Far"/>), and fall back to
/// the faithful path when the closest blocker is marked NO_SHADOW; in a scene without NO_SHADOW solids and list
/// members they stop at the first blocker once no member can contain the origin (<see cref="Occluded"/>).</para>
/// <para><b>Non-union CSG members.</b> A subtree of library CSG nodes over elementary solids is evaluated by
/// its <see cref="CsgKernel"/> (the same merged list, in stack buffers) and reports the same pair as a solid
/// (first valid record, inside state before it); its record is completed from its leaf's cached matrices.</para>
/// <para>The prepared scene is a snapshot: prepare again after changing the scene graph or attributes.</para>
/// </remarks>
public sealed partial class PreparedScene : ISceneQuery
{
  readonly PreparedMember[] members;
  readonly Matrix4d[] chain;
  readonly int[] always;
  // Some member in `always` has a line box (LineMisses); else Open needs no reciprocals of the direction.
  readonly bool lineBoxes;
  readonly RectangleCull? rectangles;
  readonly SphereCull? spheres;
  readonly WideBvh? bvh;

  // Shadow queries may stop at the first blocker: union semantics, every member answered by a kernel, no NO_SHADOW solid.
  readonly bool anyHit;

  // Union-merge semantics over all members; false: one member whose raw list the scene returns.
  readonly bool union;

  long fallbacks;

  /// <summary>The intersectable this snapshot was prepared from.</summary>
  public IIntersectable? Source { get; }

  /// <summary>Number of flattened members (leaves).</summary>
  public int MemberCount => members.Length;

  /// <summary>What the preparation decided per member (kernels, completion, shading), decided once here.</summary>
  internal SceneCapabilities Capabilities { get; }

  /// <summary>Members in the BVH.</summary>
  public int BoundedCount => Capabilities.BoundedCount;

  /// <summary>Members tested for every ray (open or unknown solids; bounded planes only where the ray's line meets their box).</summary>
  public int UnboundedCount => always.Length + (rectangles?.Count ?? 0);

  /// <summary>Bounded rectangles among the unbounded members, tested first by their conservative world-space cull (<see cref="RectangleCull"/>).</summary>
  public int CulledRectangleCount => rectangles?.Count ?? 0;

  /// <summary>Closed members tested side by side by their world balls (<see cref="SphereCull"/>) instead of a BVH.</summary>
  public int CulledBallCount => spheres?.Count ?? 0;

  /// <summary>True when shadow queries may stop at the first blocker they meet (<see cref="Occluded"/>).</summary>
  public bool StopsAtFirstBlocker => anyHit;

  /// <summary>Members answered through the LinkedList API.</summary>
  public int ListMemberCount => Capabilities.ListCount;

  /// <summary>Non-union CSG subtrees answered by their allocation-free kernel (<see cref="CsgKernel"/>).</summary>
  public int CsgMemberCount => Capabilities.CsgKernelCount;

  /// <summary>Queries of this snapshot answered by the faithful path because the fast rule did not apply.</summary>
  public long FallbackCount => Interlocked.Read(ref fallbacks);

  /// <summary>
  /// The world bounding boxes of the members that have a finite one (solids, CSG subtrees; not planes or
  /// other unbounded members), in member order: what a ray visualiser draws as the scene.
  /// </summary>
  public IReadOnlyList<(Vector3d Min, Vector3d Max)> WorldBoxes()
  {
    var boxes = new List<(Vector3d, Vector3d)>();
    foreach (PreparedMember m in members)
      if (!m.WorldBox.IsEmpty && m.WorldBox.IsFinite && Math.Abs(m.WorldBox.Max.X - m.WorldBox.Min.X) < SolidSupport.INFINITY_PLACEHOLDER)
        boxes.Add((m.WorldBox.Min, m.WorldBox.Max));
    return boxes;
  }

  PreparedScene(IIntersectable? source, bool union, PreparedMember[] members, Matrix4d[] chain, SceneCapabilities capabilities)
  {
    Source = source;
    this.union = union;
    this.members = members;
    this.chain = chain;
    Capabilities = capabilities;

    var bounded = new List<int>();
    var open = new List<int>();
    var boxes = new Aabb[members.Length];
    for (int i = 0; i < members.Length; i++)
    {
      boxes[i] = members[i].WorldBox;
      if (!members[i].Closed)
        open.Add(i);
      else if (members[i].Bounded)
        bounded.Add(i);
    }
    always = open.ToArray();
    // A few balls are tested side by side; more closed members, or others, go into the BVH.
    if (union && (spheres = SphereCull.Build(members, bounded)) == null && bounded.Count > 0)
    {
      bvh = WideBvh.Collapse(Bvh.Build(boxes, bounded.ToArray(), BvhShape.SceneMembers));
    }
    else if (!union)
      always = members.Length > 0 ? new[] { 0 } : Array.Empty<int>();
    if (union)
    {
      rectangles = RectangleCull.Build(members, chain, always, out int[] rest);
      always = rest;
      anyHit = capabilities.ListCount == 0 && !Array.Exists(members, m => m.NoShadow);
    }
    lineBoxes = Array.Exists(always, k => members[k].HasLineBox);
    PlainSurfaces = union && Array.TrueForAll(members, m => LibraryTypes.IsPlainSurface(m));
  }


  // ---------------------------------------------------------------- queries

  /// <summary>
  /// The hit <see cref="Intersection.FirstIntersection"/> would pick from the scene's list, completed
  /// with cached matrices (list members' hits are left to <see cref="Intersection.Complete"/>), or null.
  /// </summary>
  public Intersection? FirstHit(Vector3d p0, Vector3d p1) => FirstHit(p0, p1, null, false);

  /// <summary>
  /// <see cref="FirstHit(Vector3d, Vector3d)"/> that fills <paramref name="reuse"/> (reset first) instead of
  /// allocating, when the winner is a known solid; hits of list members are returned as listed.
  /// </summary>
  public Intersection? FirstHit(Vector3d p0, Vector3d p1, Intersection? reuse) => FirstHit(p0, p1, reuse, false);

  /// <inheritdoc/>
  /// <remarks>With <paramref name="needs"/> = <see cref="HitData.Surface"/>, members whose attributes allow it
  /// are completed without their local frame (<see cref="HitCompletion"/>); the computed fields are the same bits.</remarks>
  public Intersection? FirstHit(Vector3d p0, Vector3d p1, Intersection? reuse = null, HitData needs = HitData.All) =>
    FirstHit(p0, p1, reuse, (needs & HitData.LocalFrame) == 0);

  /// <inheritdoc/>
  public bool AnyHit(Vector3d p0, Vector3d dir) => Occluded(p0, dir);

  /// <summary>
  /// <see cref="FirstHit(Vector3d, Vector3d, Intersection?)"/>; with <paramref name="surfaceOnly"/> (only the library's own
  /// shading will read the hit) members that allow it are completed leanly (<see cref="HitCompletion"/>).
  /// </summary>
  // Never inlined into the shading kernel (WhittedKernel.Shade calls it per ray): inlined there, as the JIT did once Shade
  // was a little smaller, Two spheres rendered 10-12 % slower (bench/results/2026-12-07-shading-layout.md).
  [SkipLocalsInit]   // the query is started field by field, not zeroed
  [MethodImpl(MethodImplOptions.NoInlining)]
  internal Intersection? FirstHit(Vector3d p0, Vector3d p1, Intersection? reuse, bool surfaceOnly)
  {
    if (members.Length == 0)
      return null;
    double len2 = p1.LengthSquared;
    if (!union)
      return FirstHitSingle(p0, p1, len2, reuse, surfaceOnly);

    Unsafe.SkipInit(out Query q);
    q.Start(len2, double.PositiveInfinity);
    Intersection? list = null;
    if (!Closest(ref q, ref list, p0, p1))
      return ListFirstHit(p0, p1);
    if (q.InsideIndex >= 0)
    {
      // Starting inside one member: the union's first record is that member's exit, unless another
      // member is entered first (or at the same T): then the faithful path decides.
      if (q.EnteredBeforeExit)
        return ListFirstHit(p0, p1);
      return Complete(ref Solid(q.InsideIndex, q.InsideLeaf), q.InsideHit, reuse, surfaceOnly);
    }
    if (q.BestIndex == int.MaxValue)
      return null;
    return list ?? Complete(ref Solid(q.BestIndex, q.BestLeaf), q.BestHit, reuse, surfaceOnly);
  }

  /// <summary>
  /// True when every member is a plain surface (<see cref="LibraryTypes.IsPlainSurface"/>) under union semantics: the
  /// Whitted kernel may shade this scene's hits from <see cref="FirstRecord"/> without hit objects.
  /// </summary>
  internal bool PlainSurfaces { get; }

  /// <summary>Member <paramref name="index"/> as the preparation bound it.</summary>
  internal ref readonly PreparedMember Member(int index) => ref members[index];

  /// <summary>
  /// The record <see cref="FirstHit(Vector3d, Vector3d, Intersection?, bool)"/> completes, left as a record: 1 with the
  /// member and its record, 0 when the ray hits nothing, -1 when the answer is not a member's own record (a list member's
  /// hit, a CSG leaf's, or the faithful path's), which <see cref="FirstHit(Vector3d, Vector3d, Intersection?, bool)"/> gives.
  /// </summary>
  [SkipLocalsInit]   // the query is started field by field, not zeroed
  [MethodImpl(MethodImplOptions.NoInlining)]   // as FirstHit: kept out of the shading kernel
  internal int FirstRecord(in Vector3d p0, in Vector3d p1, out int member, out SolidRecord hit)
  {
    member = -1;
    hit = default;
    if (!union)
      return members.Length == 0 ? 0 : -1;
    Unsafe.SkipInit(out Query q);
    q.Start(p1.LengthSquared, double.PositiveInfinity);
    Intersection? list = null;
    if (!Closest(ref q, ref list, p0, p1))
      return -1;
    if (q.InsideIndex >= 0)
    {
      // As FirstHit: the inside member's exit, unless another member is entered first (or at the same T).
      if (q.EnteredBeforeExit || q.InsideLeaf >= 0)
        return -1;
      member = q.InsideIndex;
      hit = q.InsideHit;
      return 1;
    }
    if (q.BestIndex == int.MaxValue)
      return 0;
    if (list != null || q.BestLeaf >= 0)
      return -1;
    member = q.BestIndex;
    hit = q.BestHit;
    return 1;
  }

  /// <summary>The solid a record belongs to: the member itself, or leaf <paramref name="leaf"/> of its CSG kernel.</summary>
  ref PreparedMember Solid(int member, int leaf)
  {
    if (leaf < 0)
      return ref members[member];
    return ref members[member].Csg!.Leaves[leaf];
  }

  /// <summary>The record as an <see cref="Intersection"/>, completed from the member's cached matrices and attributes.</summary>
  static Intersection Complete(ref PreparedMember m, in SolidRecord hit, Intersection? reuse, bool surfaceOnly)
  {
    IRecordSolid f = m.RecordSolid!;
    Intersection i;
    if (reuse != null)
    {
      reuse.Reset(f);
      i = reuse;
    }
    else
      i = new Intersection(f);
    LibraryTypes.Init(m.Direct, f, hit, i);
    if (surfaceOnly && m.Completion != HitCompletion.Full)
    {
      if (!i.BeginSurface(m.LocalToWorld, m.Model!, m.Material!, m.Color, m.Textures, m.Recursion))
        return i;
      if (LibraryTypes.CompleteSurface(m.Completion, i, m.WorldToLocal))
      {
        i.EndSurface();
        return i;
      }
      // The solid asked for the full completion of this hit.
    }
    if (m.AttributesCached)
      i.CompleteCached(m.LocalToWorld, m.WorldToLocal, m.LocalToObject, m.Model!, m.Material!, m.Color, m.Textures, m.Recursion);
    else
      i.CompleteWith(m.LocalToWorld, m.WorldToLocal, m.LocalToObject);
    return i;
  }

  /// <summary>
  /// True when a hit not marked NO_SHADOW lies between <paramref name="p0"/> and <c>p0 + dir</c>
  /// (the faithful rule: FirstRealIntersection, then not <see cref="Intersection.Far"/>(1)).
  /// </summary>
  // Not inlined into its callers (AnyHit, RayTracing's shadow test): each of those is compiled again at tier 1 while
  // a render starts, and a copy of this body in each tripled the JIT's work on the way to the first fast pixels.
  [SkipLocalsInit]   // the query is started field by field, not zeroed
  [MethodImpl(MethodImplOptions.NoInlining)]
  public bool Occluded(Vector3d p0, Vector3d dir)
  {
    if (members.Length == 0)
      return false;
    double len2 = dir.LengthSquared;
    if (!union)
      return OccludedSingle(p0, dir, len2);

    double bound = FarBound(len2);
    double invLength = CullBounds.UpperInverseLength(len2);
    Unsafe.SkipInit(out Query q);
    q.Start(len2, bound);
    Intersection? list = null;
    if (anyHit)
    {
      // With no NO_SHADOW solid, a blocker that is not far decides, once no member is inside at the origin:
      // every member's first record is then an entry, so the union's first record is no later than it.
      q.Any = true;
      q.AnyBound = 1.001 * Intersection.RAY_EPSILON * invLength;
      if (!Closest(ref q, ref list, p0, dir))
        return ListOccluded(p0, dir);
      if (!q.Found)
        return Decide(ref q, list, p0, dir, len2);
      if (q.InsideIndex < 0)
        return true;
      // Inside a member: the closest-record rule decides, as without the shortcut.
      q.Start(len2, bound);
      list = null;
    }
    if (!Closest(ref q, ref list, p0, dir))
      return ListOccluded(p0, dir);
    return Decide(ref q, list, p0, dir, len2);
  }

  /// <summary>The shadow answer from a completed closest-record query.</summary>
  bool Decide(ref Query q, Intersection? list, Vector3d p0, Vector3d dir, double len2)
  {
    if (q.InsideIndex >= 0)
    {
      if (q.EnteredBeforeExit || Solid(q.InsideIndex, q.InsideLeaf).NoShadow)
        return ListOccluded(p0, dir);
      return NotFar(q.InsideT, len2);
    }
    if (q.BestIndex == int.MaxValue)
      return false;

    bool noShadow = list != null
      ? list.Solid != null && list.Solid.GetLocalAttribute(PropertyName.NO_SHADOW) != null
      : Solid(q.BestIndex, q.BestLeaf).NoShadow;
    if (noShadow)
      return ListOccluded(p0, dir);
    return NotFar(q.EntryT, len2);
  }

  /// <summary>
  /// Hits beyond 1 + RAY_EPSILON/|dir| are Far(1): a bound to prune them with a little slack (tested exactly by
  /// <see cref="NotFar"/>), from an upper bound on 1/|dir| (it may only be larger: more is tested exactly, nothing is lost).
  /// </summary>
  static double FarBound(double len2)
  {
    double bound = 1.0 + Intersection.RAY_EPSILON * CullBounds.UpperInverseLength(len2);
    return bound + bound * 1.0e-12;
  }

  /// <summary>
  /// Not <see cref="Intersection.Far"/>(1) for a record at <paramref name="t"/> of a ray with |dir|² = <paramref name="len2"/>
  /// (the same arithmetic). Monotone: true at t is true at every smaller t.
  /// </summary>
  internal static bool NotFar(double t, double len2)
  {
    if (t <= 1.0)
      return true;
    double d = t - 1.0;
    return !(d * d * len2 > Intersection.RAY_EPSILON2);
  }

  Intersection? ListFirstHit(Vector3d p0, Vector3d p1)
  {
    Interlocked.Increment(ref fallbacks);
    return Intersection.FirstIntersection(Source!.Intersect(p0, p1), ref p1);
  }

  bool ListOccluded(Vector3d p0, Vector3d dir)
  {
    Interlocked.Increment(ref fallbacks);
    Intersection? si = Intersection.FirstRealIntersection(Source!.Intersect(p0, dir), ref dir);
    return si != null && !si.Far(1.0, ref dir);
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  void ToLocal(in PreparedMember m, ref Vector3d p0, ref Vector3d p1)
  {
    // Same arithmetic, in the same order, as Vector3d.TransformPosition/TransformVector (bit-identical),
    // reading the matrix by reference instead of copying 128 bytes per step.
    int end = m.ChainStart + m.ChainCount;
    for (int k = m.ChainStart; k < end; k++)
      CsgKernel.Transform(ref chain[k], ref p0, ref p1);
  }

  Intersection? FirstHitSingle(Vector3d p0, Vector3d p1, double len2, Intersection? reuse, bool surfaceOnly)
  {
    ref PreparedMember m = ref members[0];
    Vector3d lp0 = p0, lp1 = p1;
    ToLocal(m, ref lp0, ref lp1);
    if (m.RecordSolid != null)
    {
      // The raw list's first record: the state before it is not needed.
      if (!LibraryTypes.FirstRecord(m.Direct, m.RecordSolid, lp0, lp1, len2, double.PositiveInfinity, out SolidRecord h))
        return null;
      return Complete(ref m, h, reuse, surfaceOnly);
    }
    if (m.Csg != null)
    {
      int status = m.Csg.IntersectFirst(lp0, lp1, len2, out SolidRecord h, out int leaf, out _);
      if (status == 0)
        return null;
      if (status > 0)
        return Complete(ref m.Csg.Leaves[leaf], h, reuse, surfaceOnly);
    }
    return Intersection.FirstIntersection(m.Node.Intersect(lp0, lp1), ref p1);
  }

  bool OccludedSingle(Vector3d p0, Vector3d dir, double len2)
  {
    ref PreparedMember m = ref members[0];
    Vector3d lp0 = p0, lp1 = dir;
    ToLocal(m, ref lp0, ref lp1);
    if (m.RecordSolid != null)
    {
      // Every record belongs to this solid, so NO_SHADOW hides them all. A record beyond the bound is far (Occluded's
      // bound), so the search stops there; the mesh may stop at an earlier blocker it proves.
      return !m.NoShadow && LibraryTypes.Occluded(m.Direct, m.RecordSolid, lp0, lp1, len2, FarBound(len2));
    }
    if (m.Csg != null)
    {
      // FirstRealIntersection skips NO_SHADOW records: the list decides when the first one is such.
      int status = m.Csg.IntersectFirst(lp0, lp1, len2, out SolidRecord h, out int leaf, out _);
      if (status == 0)
        return false;
      if (status > 0 && !m.Csg.Leaves[leaf].NoShadow)
        return NotFar(h.T, len2);
    }
    Intersection? si = Intersection.FirstRealIntersection(m.Node.Intersect(lp0, lp1), ref dir);
    return si != null && !si.Far(1.0, ref dir);
  }
}
