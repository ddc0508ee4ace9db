using Scene3D;
using System;
using System.Buffers;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// A mesh's triangles under the generic <see cref="Bvh"/>, with the two allocation-free traversals a
/// mesh needs: every hit along the whole line (negative t included, because CSG needs the complete
/// list) and the nearest accepted or last rejected hit (on the tree collapsed to four children per node,
/// <see cref="WideBvh"/>). Triangles are stored in leaf order and tested
/// with Möller–Trumbore (<see cref="MeshTriangles"/>).
/// </summary>
internal sealed class MeshBvh
{
  readonly Bvh tree;
  readonly WideBvh wide;
  readonly double[] tri;      // 9 doubles per triangle in leaf order: a, b − a, c − a
  readonly int[] triId;       // leaf order → original triangle handle

  public int TriangleCount => triId.Length;

  public int NodeCount => tree.Nodes.Length;

  /// <summary>Nodes of the four-wide tree the fast queries walk.</summary>
  public int WideNodeCount => wide.Nodes.Length;

  /// <summary>Size of the mesh's box (for relative tolerances).</summary>
  public double Extent { get; }

  public MeshBvh(SceneBrep mesh)
  {
    int n = mesh.Triangles;
    // Only the build reads boxes and centroids: lent by the pool (each is a large-object-heap array otherwise).
    Aabb[] boxes = ArrayPool<Aabb>.Shared.Rent(n);
    Vector3d[] centroids = ArrayPool<Vector3d>.Shared.Rent(n);
    var order = new int[n];
    // Per triangle, independent: in parallel chunks (the results do not depend on how they are cut).
    InChunks(n, (start, end) =>
    {
      for (int i = start; i < end; i++)
      {
        mesh.GetTriangleVertices(i, out Vector3 pa, out Vector3 pb, out Vector3 pc);
        Vector3d a = pa, b = pb, c = pc;
        boxes[i] = new Aabb(Vector3d.ComponentMin(a, Vector3d.ComponentMin(b, c)), Vector3d.ComponentMax(a, Vector3d.ComponentMax(b, c)));
        centroids[i] = (a + b + c) / 3.0;
        order[i] = i;
      }
    });

    tree = Bvh.Build(boxes, centroids, order, BvhShape.Triangles);
    ArrayPool<Aabb>.Shared.Return(boxes);
    ArrayPool<Vector3d>.Shared.Return(centroids);
    // The child-box padding lies far above rounding (of box and triangle arithmetic, also far from the
    // origin) and far below any feature: the two-box test may then only keep more boxes, never fewer.
    // The root box is the union of every triangle's box.
    Aabb root = n > 0 ? new Aabb(new Vector3d(tree.Nodes[0].MinX, tree.Nodes[0].MinY, tree.Nodes[0].MinZ),
                                 new Vector3d(tree.Nodes[0].MaxX, tree.Nodes[0].MaxY, tree.Nodes[0].MaxZ)) : Aabb.Empty;
    Extent = n > 0 ? (root.Max - root.Min).Length : 0.0;
    double magnitude = 0.0;
    for (int axis = 0; axis < 3 && n > 0; axis++)
      magnitude = Math.Max(magnitude, Math.Max(Math.Abs(root.Min[axis]), Math.Abs(root.Max[axis])));
    wide = WideBvh.Collapse(tree, 1e-9 * (Extent + magnitude));

    double[] stored = tri = new double[9 * n];
    triId = order;
    InChunks(n, (start, end) =>
    {
      for (int k = start; k < end; k++)
      {
        // The vertices again from the mesh (cheap) rather than three more large arrays for the collector.
        mesh.GetTriangleVertices(order[k], out Vector3 pa, out Vector3 pb, out Vector3 pc);
        MeshTriangles.Store(stored, 9 * k, pa, pb, pc);
      }
    });
  }

  /// <summary>body(start, end) over [0, n) cut in chunks, in parallel when there are enough.</summary>
  static void InChunks(int n, Action<int, int> body)
  {
    const int Chunk = 8192;
    if (n <= Chunk)
    {
      body(0, n);
      return;
    }
    System.Threading.Tasks.Parallel.For(0, (n + Chunk - 1) / Chunk, k => body(k * Chunk, Math.Min(n, (k + 1) * Chunk)));
  }

  /// <summary>Original triangle handle of the k-th triangle in leaf order.</summary>
  public int OriginalTriangle(int k) => triId[k];

  /// <summary>Appends all hits of the line <c>p0 + t p1</c> (any t) to <paramref name="hits"/>, unsorted.</summary>
  public void IntersectAll(Vector3d p0, Vector3d p1, List<MeshHit> hits)
  {
    if (triId.Length == 0)
      return;
    double ox = p0.X, oy = p0.Y, oz = p0.Z, dx = p1.X, dy = p1.Y, dz = p1.Z;
    double ix = 1.0 / dx, iy = 1.0 / dy, iz = 1.0 / dz;

    Span<int> stack = stackalloc int[128];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0)
    {
      int node = stack[--sp];
      if (!LineBox(node, ox, oy, oz, dx, dy, dz, ix, iy, iz, out _, out _))
        continue;
      ref BvhNode n = ref tree.Nodes[node];
      if (n.Count == 0)
      {
        if (sp + 2 > stack.Length)
        {
          // Degenerate (very deep) tree: fall back to a heap stack once.
          Span<int> bigger = new int[stack.Length * 2];
          stack.CopyTo(bigger);
          stack = bigger;
        }
        stack[sp++] = node + 1;
        stack[sp++] = n.Index;
        continue;
      }
      int end = n.Index + n.Count;
      for (int k = n.Index; k < end; k++)
        TestTriangle(k, ox, oy, oz, dx, dy, dz, hits);
    }
  }

  static bool Slab(double min, double max, double o, double d, double inv, ref double tMin, ref double tMax)
  {
    if (d == 0.0)
      return o >= min && o <= max;
    double t0 = (min - o) * inv, t1 = (max - o) * inv;
    if (t0 > t1)
      (t0, t1) = (t1, t0);
    // Widen a little so that hits on box faces (flat boxes) are not lost to rounding.
    double pad = 1e-12 * (Math.Abs(t0) + Math.Abs(t1));
    tMin = Math.Max(tMin, t0 - pad);
    tMax = Math.Min(tMax, t1 + pad);
    return tMin <= tMax;
  }

  void TestTriangle(int k, double ox, double oy, double oz, double dx, double dy, double dz, List<MeshHit> hits)
  {
    if (Triangle(k, ox, oy, oz, dx, dy, dz, out double t, out double u, out double v, out bool front))
      hits.Add(new MeshHit { T = t, Triangle = triId[k], U = u, V = v, Front = front });
  }

  /// <summary>Möller–Trumbore against the k-th triangle in leaf order.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  bool Triangle(int k, double ox, double oy, double oz, double dx, double dy, double dz,
                out double t, out double u, out double v, out bool front) =>
    MeshTriangles.Hit(tri, 9 * k, ox, oy, oz, dx, dy, dz, out t, out u, out v, out front);

  /// <summary>
  /// The first hit in the list's order (T, then triangle) among hits <see cref="Intersection.FirstIntersection"/>
  /// accepts (<c>T &gt; 0</c>, <c>T² len2 &gt; RAY_EPSILON2</c>) when <paramref name="accepted"/>; otherwise the
  /// last hit in that order among those it rejects. Allocation-free, nearest boxes first, pruned by the best so far.
  /// </summary>
  [SkipLocalsInit]   // the stack is written before it is read: no zeroing of it per query
  public bool Nearest(in Vector3d p0, in Vector3d p1, double len2, bool accepted, out MeshHit best)
  {
    best = default;
    if (triId.Length == 0)
      return false;
    double ox = p0.X, oy = p0.Y, oz = p0.Z, dx = p1.X, dy = p1.Y, dz = p1.Z;
    double ix = 1.0 / dx, iy = 1.0 / dy, iz = 1.0 / dz;

    // Rejected hits have T ≤ sqrt(RAY_EPSILON2 / len2) (up to rounding; the exact test decides).
    double limit = Math.Sqrt(Intersection.RAY_EPSILON2 / len2);
    limit += 1e-9 * limit + 1e-300;
    bool found = false;
    double bestT = accepted ? double.PositiveInfinity : double.NegativeInfinity;
    int bestTri = 0;
    if (!LineBox(0, ox, oy, oz, dx, dy, dz, ix, iy, iz, out double rootNear, out double rootFar))
      return false;
    Vector256<double> vox = Vector256.Create(ox), voy = Vector256.Create(oy), voz = Vector256.Create(oz);
    Vector256<double> vix = Vector256.Create(ix), viy = Vector256.Create(iy), viz = Vector256.Create(iz);
    WideNode[] nodes = wide.Nodes;

    // Each entry: an inner node (≥ 0) or a leaf lane (~(node·4 + lane)) and the line's parameter interval in its box,
    // re-checked against the best when popped; the root's interval is that of the whole mesh's box.
    int size = wide.StackSize;
    // On the stack (not zeroed) up to a tree depth of about 170; only a degenerate mesh's tree is deeper.
    Span<NodeSpan> stack = size <= 512 ? stackalloc NodeSpan[size] : new NodeSpan[size];
    int sp = 0;
    stack[sp++] = new NodeSpan(0, rootNear, rootFar);
    while (sp > 0)
    {
      NodeSpan e = stack[--sp];
      // Accepted: T in (0, best]; rejected: T in [best, limit].
      if (accepted ? (e.Far <= 0.0 || e.Near > bestT) : (e.Near > limit || e.Far < bestT))
        continue;
      int code = e.Node;
      if (code >= 0)
      {
        ref WideNode n = ref nodes[code];
        int mask = n.Cross(vox, voy, voz, vix, viy, viz, out Vector256<double> near, out Vector256<double> far);
        // The boxes more likely to hold the answer are popped first: nearest entry for the first accepted hit,
        // farthest exit for the last rejected one. Pushed in insertion order, most likely last.
        int first = sp;
        for (; mask != 0; mask &= mask - 1)
        {
          int lane = System.Numerics.BitOperations.TrailingZeroCount(mask);
          var s = new NodeSpan(n.Count[lane] == 0 ? n.Index[lane] : ~(code * WideNode.Width + lane), near.GetElement(lane), far.GetElement(lane));
          int k = sp++;
          for (; k > first && (accepted ? stack[k - 1].Near < s.Near : stack[k - 1].Far > s.Far); k--)
            stack[k] = stack[k - 1];
          stack[k] = s;
        }
        continue;
      }
      int slot = ~code;
      ref WideNode parent = ref nodes[slot / WideNode.Width];
      int start = parent.Index[slot % WideNode.Width], end = start + parent.Count[slot % WideNode.Width];
      for (int k = start; k < end; k++)
      {
        if (!Triangle(k, ox, oy, oz, dx, dy, dz, out double t, out double u, out double v, out bool front))
          continue;
        if ((t > 0.0 && t * t * len2 > Intersection.RAY_EPSILON2) != accepted)
          continue;
        int id = triId[k];
        bool better = accepted
          ? t < bestT || (t == bestT && id < bestTri)
          : t > bestT || (t == bestT && id > bestTri);
        if (!found || better)
        {
          found = true;
          bestT = t;
          bestTri = id;
          best = new MeshHit { T = t, Triangle = id, U = u, V = v, Front = front };
        }
      }
    }
    return found;
  }

  /// <summary>
  /// Any-hit with early exit: some hit that <see cref="Intersection.FirstIntersection"/> accepts with T ≤ <paramref name="tMax"/>
  /// and runs against the face (Front). True at the first such hit found, in no particular order; otherwise false, with
  /// <paramref name="onlyBack"/> true when accepted back-face hits (exits) lie in that range. Boxes beyond
  /// <paramref name="tMax"/> or behind the origin are never opened.
  /// </summary>
  [SkipLocalsInit]   // the stack is written before it is read
  public bool AnyFront(in Vector3d p0, in Vector3d p1, double len2, double tMax, out MeshHit hit, out bool onlyBack)
  {
    hit = default;
    onlyBack = false;
    if (triId.Length == 0)
      return false;
    double ox = p0.X, oy = p0.Y, oz = p0.Z, dx = p1.X, dy = p1.Y, dz = p1.Z;
    double ix = 1.0 / dx, iy = 1.0 / dy, iz = 1.0 / dz;
    if (!LineBox(0, ox, oy, oz, dx, dy, dz, ix, iy, iz, out double rootNear, out double rootFar) || rootFar <= 0.0 || rootNear > tMax)
      return false;
    Vector256<double> vox = Vector256.Create(ox), voy = Vector256.Create(oy), voz = Vector256.Create(oz);
    Vector256<double> vix = Vector256.Create(ix), viy = Vector256.Create(iy), viz = Vector256.Create(iz);
    WideNode[] nodes = wide.Nodes;

    // Entries as in Nearest: an inner node (≥ 0) or a leaf lane (~(node·4 + lane)); only boxes meeting (0, tMax] are pushed.
    int size = wide.StackSize;
    Span<int> stack = size <= 1024 ? stackalloc int[size] : new int[size];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0)
    {
      int code = stack[--sp];
      if (code >= 0)
      {
        ref WideNode n = ref nodes[code];
        int mask = n.Cross(vox, voy, voz, vix, viy, viz, out Vector256<double> near, out Vector256<double> far);
        for (; mask != 0; mask &= mask - 1)
        {
          int lane = System.Numerics.BitOperations.TrailingZeroCount(mask);
          if (far.GetElement(lane) <= 0.0 || near.GetElement(lane) > tMax)
            continue;
          stack[sp++] = n.Count[lane] == 0 ? n.Index[lane] : ~(code * WideNode.Width + lane);
        }
        continue;
      }
      int slot = ~code;
      ref WideNode parent = ref nodes[slot / WideNode.Width];
      int start = parent.Index[slot % WideNode.Width], end = start + parent.Count[slot % WideNode.Width];
      for (int k = start; k < end; k++)
      {
        if (!Triangle(k, ox, oy, oz, dx, dy, dz, out double t, out double u, out double v, out bool front))
          continue;
        if (!(t > 0.0 && t * t * len2 > Intersection.RAY_EPSILON2) || t > tMax)
          continue;
        if (!front)
        {
          onlyBack = true;
          continue;
        }
        hit = new MeshHit { T = t, Triangle = triId[k], U = u, V = v, Front = true };
        onlyBack = false;
        return true;
      }
    }
    return false;
  }

  /// <summary>Parameter interval of the line in a node's box (the same widened slabs as <see cref="IntersectAll"/>).</summary>
  bool LineBox(int node, double ox, double oy, double oz, double dx, double dy, double dz, double ix, double iy, double iz,
               out double tMin, out double tMax)
  {
    ref BvhNode n = ref tree.Nodes[node];
    tMin = double.NegativeInfinity;
    tMax = double.PositiveInfinity;
    return Slab(n.MinX, n.MaxX, ox, dx, ix, ref tMin, ref tMax) &&
           Slab(n.MinY, n.MaxY, oy, dy, iy, ref tMin, ref tMax) &&
           Slab(n.MinZ, n.MaxZ, oz, dz, iz, ref tMin, ref tMax);
  }

  readonly record struct NodeSpan(int Node, double Near, double Far);
}
