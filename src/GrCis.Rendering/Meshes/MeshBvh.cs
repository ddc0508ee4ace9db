using Scene3D;
using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>One ray–triangle hit found by <see cref="MeshBvh"/>.</summary>
internal struct MeshHit
{
  public double T;
  public int Triangle;
  public double U, V;   // barycentrics: p = (1 − u − v)·a + u·b + v·c
  public bool Front;    // the ray runs against the geometric normal (b − a) × (c − a)
}

/// <summary>
/// Bounding volume hierarchy over a triangle soup: binned SAH build, nodes in flat arrays
/// (a node's children are adjacent), allocation-free traversal with an explicit stack and
/// Möller–Trumbore tests. It reports every hit along the whole line (negative t included),
/// because CSG needs the complete list.
/// </summary>
internal sealed class MeshBvh
{
  const int Bins = 16;
  const int MaxLeafSize = 4;
  const double TraversalCost = 1.0;
  const double TriangleCost = 1.0;

  // Triangles in leaf order: first vertex and the two edges.
  readonly double[] tri;      // 9 doubles per triangle: a, b − a, c − a
  readonly int[] triId;       // original triangle handle

  // Nodes: box, then either (first triangle, count > 0) or (left child index, count = 0); right = left + 1.
  double[] boxes = Array.Empty<double>();   // 6 per node: min xyz, max xyz
  int[] firstOrLeft = Array.Empty<int>();
  int[] counts = Array.Empty<int>();
  int nodeCount;
  // Inner node with children (left, left + 1) → its padded child boxes at (left − 1) / 2, for Nearest.
  MeshChildBoxes[] childBoxes = Array.Empty<MeshChildBoxes>();

  public int TriangleCount => triId.Length;

  public int NodeCount => nodeCount;

  /// <summary>Size of the mesh's box (for relative tolerances).</summary>
  public double Extent { get; }

  public MeshBvh(SceneBrep mesh)
  {
    int n = mesh.Triangles;
    var a = new Vector3d[n];
    var b = new Vector3d[n];
    var c = new Vector3d[n];
    for (int i = 0; i < n; i++)
    {
      mesh.GetTriangleVertices(i, out Vector3 pa, out Vector3 pb, out Vector3 pc);
      a[i] = pa;
      b[i] = pb;
      c[i] = pc;
    }

    // Per-triangle bounds and centroids.
    var lo = new Vector3d[n];
    var hi = new Vector3d[n];
    var centroid = new Vector3d[n];
    var order = new int[n];
    for (int i = 0; i < n; i++)
    {
      lo[i] = Vector3d.ComponentMin(a[i], Vector3d.ComponentMin(b[i], c[i]));
      hi[i] = Vector3d.ComponentMax(a[i], Vector3d.ComponentMax(b[i], c[i]));
      centroid[i] = (a[i] + b[i] + c[i]) / 3.0;
      order[i] = i;
    }

    int maxNodes = Math.Max(1, 2 * n - 1);
    boxes = new double[6 * maxNodes];
    firstOrLeft = new int[maxNodes];
    counts = new int[maxNodes];
    nodeCount = 1;
    if (n > 0)
      Build(0, 0, n, order, lo, hi, centroid);
    else
      SetBox(0, Vector3d.Zero, Vector3d.Zero);
    Extent = n > 0 ? new Vector3d(boxes[3] - boxes[0], boxes[4] - boxes[1], boxes[5] - boxes[2]).Length : 0.0;

    // Padding far above rounding (of box and triangle arithmetic, also far from the origin), far below any
    // feature: the two-box test may then only keep more boxes than an exact one, never fewer.
    double magnitude = 0.0;
    for (int k = 0; k < 6 && n > 0; k++)
      magnitude = Math.Max(magnitude, Math.Abs(boxes[k]));
    double pad = 1e-9 * (Extent + magnitude);
    childBoxes = new MeshChildBoxes[Math.Max(0, (nodeCount - 1) / 2)];
    for (int node = 0; node < nodeCount; node++)
      if (counts[node] == 0 && n > 0)
        childBoxes[(firstOrLeft[node] - 1) / 2] = new MeshChildBoxes(boxes, firstOrLeft[node], pad);

    tri = new double[9 * n];
    triId = new int[n];
    for (int k = 0; k < n; k++)
    {
      int i = order[k];
      triId[k] = i;
      MeshTriangles.Store(tri, 9 * k, a[i], b[i], c[i]);
    }
  }

  void SetBox(int node, Vector3d min, Vector3d max)
  {
    int o = 6 * node;
    boxes[o] = min.X; boxes[o + 1] = min.Y; boxes[o + 2] = min.Z;
    boxes[o + 3] = max.X; boxes[o + 4] = max.Y; boxes[o + 5] = max.Z;
  }

  static double HalfArea(Vector3d min, Vector3d max)
  {
    Vector3d d = max - min;
    return d.X * d.Y + d.Y * d.Z + d.Z * d.X;
  }

  void Build(int node, int first, int count, int[] order, Vector3d[] lo, Vector3d[] hi, Vector3d[] centroid)
  {
    Vector3d bMin = Vector3d.PositiveInfinity, bMax = Vector3d.NegativeInfinity;
    Vector3d cMin = Vector3d.PositiveInfinity, cMax = Vector3d.NegativeInfinity;
    for (int k = first; k < first + count; k++)
    {
      int i = order[k];
      bMin = Vector3d.ComponentMin(bMin, lo[i]);
      bMax = Vector3d.ComponentMax(bMax, hi[i]);
      cMin = Vector3d.ComponentMin(cMin, centroid[i]);
      cMax = Vector3d.ComponentMax(cMax, centroid[i]);
    }
    SetBox(node, bMin, bMax);
    firstOrLeft[node] = first;
    counts[node] = count;
    if (count <= MaxLeafSize)
      return;

    // Binned SAH over all three axes of the centroid box.
    Span<int> binCount = stackalloc int[Bins];
    Span<Vector3d> binLo = stackalloc Vector3d[Bins];
    Span<Vector3d> binHi = stackalloc Vector3d[Bins];
    Span<double> rightArea = stackalloc double[Bins];
    Span<int> rightCount = stackalloc int[Bins];
    double bestCost = double.PositiveInfinity;
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; axis++)
    {
      double extent = cMax[axis] - cMin[axis];
      if (!(extent > 0.0))
        continue;
      double scale = Bins / extent;
      binCount.Clear();
      binLo.Fill(Vector3d.PositiveInfinity);
      binHi.Fill(Vector3d.NegativeInfinity);
      for (int k = first; k < first + count; k++)
      {
        int i = order[k];
        int bin = Math.Min(Bins - 1, (int)((centroid[i][axis] - cMin[axis]) * scale));
        binCount[bin]++;
        binLo[bin] = Vector3d.ComponentMin(binLo[bin], lo[i]);
        binHi[bin] = Vector3d.ComponentMax(binHi[bin], hi[i]);
      }
      // Sweep from the right, then from the left evaluating each split plane.
      Vector3d rl = Vector3d.PositiveInfinity, rh = Vector3d.NegativeInfinity;
      int rc = 0;
      for (int s = Bins - 1; s > 0; s--)
      {
        rc += binCount[s];
        rl = Vector3d.ComponentMin(rl, binLo[s]);
        rh = Vector3d.ComponentMax(rh, binHi[s]);
        rightCount[s] = rc;
        rightArea[s] = rc > 0 ? HalfArea(rl, rh) : 0.0;
      }
      Vector3d ll = Vector3d.PositiveInfinity, lh = Vector3d.NegativeInfinity;
      int lc = 0;
      for (int s = 1; s < Bins; s++)
      {
        lc += binCount[s - 1];
        ll = Vector3d.ComponentMin(ll, binLo[s - 1]);
        lh = Vector3d.ComponentMax(lh, binHi[s - 1]);
        if (lc == 0 || rightCount[s] == 0)
          continue;
        double cost = lc * HalfArea(ll, lh) + rightCount[s] * rightArea[s];
        if (cost < bestCost)
        {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = s;
        }
      }
    }

    double leafCost = count * TriangleCost;
    double parentArea = HalfArea(bMin, bMax);
    double splitCost = parentArea > 0.0 ? TraversalCost + TriangleCost * bestCost / parentArea : double.PositiveInfinity;
    int mid;
    if (bestAxis >= 0 && splitCost < leafCost)
    {
      double scale = Bins / (cMax[bestAxis] - cMin[bestAxis]);
      int i0 = first, i1 = first + count - 1;
      while (i0 <= i1)
      {
        int bin = Math.Min(Bins - 1, (int)((centroid[order[i0]][bestAxis] - cMin[bestAxis]) * scale));
        if (bin < bestSplit)
          i0++;
        else
        {
          (order[i0], order[i1]) = (order[i1], order[i0]);
          i1--;
        }
      }
      mid = i0;
    }
    else if (count > 4 * MaxLeafSize)
    {
      // SAH prefers a leaf but it is large: split in the middle of the order (median).
      mid = first + count / 2;
    }
    else
      return;

    if (mid == first || mid == first + count)
      mid = first + count / 2;
    int left = nodeCount;
    nodeCount += 2;
    firstOrLeft[node] = left;
    counts[node] = 0;
    Build(left, first, mid - first, order, lo, hi, centroid);
    Build(left + 1, mid, first + count - mid, order, lo, hi, centroid);
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
      int count = counts[node];
      if (count == 0)
      {
        if (sp + 2 > stack.Length)
        {
          // Degenerate (very deep) tree: fall back to a heap stack once.
          Span<int> bigger = new int[stack.Length * 2];
          stack.CopyTo(bigger);
          stack = bigger;
        }
        stack[sp++] = firstOrLeft[node];
        stack[sp++] = firstOrLeft[node] + 1;
        continue;
      }
      int end = firstOrLeft[node] + count;
      for (int k = firstOrLeft[node]; k < end; k++)
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
    Vector128<double> vox = Vector128.Create(ox), voy = Vector128.Create(oy), voz = Vector128.Create(oz);
    Vector128<double> vix = Vector128.Create(ix), viy = Vector128.Create(iy), viz = Vector128.Create(iz);

    // Each entry: a node and the line's parameter interval in its box, re-checked against the best when popped.
    Span<NodeSpan> stack = stackalloc NodeSpan[128];
    int sp = 0;
    stack[sp++] = new NodeSpan(0, rootNear, rootFar);
    while (sp > 0)
    {
      NodeSpan e = stack[--sp];
      // Accepted: T in (0, best]; rejected: T in [best, limit].
      if (accepted ? (e.Far <= 0.0 || e.Near > bestT) : (e.Near > limit || e.Far < bestT))
        continue;
      int node = e.Node;
      int count = counts[node];
      if (count == 0)
      {
        int left = firstOrLeft[node];
        int mask = childBoxes[(left - 1) >> 1].Cross(vox, voy, voz, vix, viy, viz, out Vector128<double> near, out Vector128<double> far);
        if (mask == 0)
          continue;
        if (sp + 2 > stack.Length)
        {
          // Degenerate (very deep) tree: a heap stack once.
          Span<NodeSpan> bigger = new NodeSpan[stack.Length * 2];
          stack.CopyTo(bigger);
          stack = bigger;
        }
        var l = new NodeSpan(left, near.GetElement(0), far.GetElement(0));
        var r = new NodeSpan(left + 1, near.GetElement(1), far.GetElement(1));
        if (mask != 3)
        {
          stack[sp++] = mask == 1 ? l : r;
          continue;
        }
        // The child more likely to hold the answer is popped first: nearest entry for the first accepted
        // hit, farthest exit for the last rejected one.
        bool rightFirst = accepted ? r.Near < l.Near : r.Far > l.Far;
        stack[sp++] = rightFirst ? l : r;
        stack[sp++] = rightFirst ? r : l;
        continue;
      }
      int end = firstOrLeft[node] + count;
      for (int k = firstOrLeft[node]; k < end; k++)
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

  /// <summary>Parameter interval of the line in a node's box (the same widened slabs as <see cref="IntersectAll"/>).</summary>
  bool LineBox(int node, double ox, double oy, double oz, double dx, double dy, double dz, double ix, double iy, double iz,
               out double tMin, out double tMax)
  {
    int o = 6 * node;
    tMin = double.NegativeInfinity;
    tMax = double.PositiveInfinity;
    return Slab(boxes[o], boxes[o + 3], ox, dx, ix, ref tMin, ref tMax) &&
           Slab(boxes[o + 1], boxes[o + 4], oy, dy, iy, ref tMin, ref tMax) &&
           Slab(boxes[o + 2], boxes[o + 5], oz, dz, iz, ref tMin, ref tMax);
  }

  readonly record struct NodeSpan(int Node, double Near, double Far);
}
