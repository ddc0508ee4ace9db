using Scene3D;
using System;
using System.Buffers;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// A mesh's triangles under the generic <see cref="Bvh"/>, collapsed to eight children per node with float boxes
/// (<see cref="MeshNode"/>, tested eight at a time by <see cref="FloatStep"/>), with the allocation-free traversals a mesh needs: every hit along the whole line (negative t included, because CSG
/// needs the complete list), the nearest accepted and last rejected hit (<c>MeshBvh.Queries.cs</c>) and an any-hit
/// walk. A leaf's triangles are stored four at a time in leaf order (<see cref="TriangleBlock"/>) and tested with
/// Möller–Trumbore in exactly <see cref="MeshTriangles"/>' arithmetic, so every query finds the hits, to the bit, that
/// testing every triangle finds.
/// </summary>
internal sealed partial class MeshBvh
{
  // The nodes (leaf lanes: Index = first block of the leaf, Count = its blocks) in a pinned buffer from a 64-byte boundary on:
  // a node is then four whole cache lines and no 32-byte load straddles two (a managed array is only 8-byte aligned).
  readonly byte[] nodeMemory;
  readonly int nodeStart, nodeCount;
  readonly int stackSize;     // traversal stack entries that can be live at once
  readonly BvhNode root;      // the box around every triangle
  readonly double mx, my, mz; // largest |coordinate| of the float boxes per axis, +∞ when a box is not finite in floats
  // The triangle blocks likewise from a 64-byte boundary on: a block (160 bytes) then spans three cache lines, not four.
  readonly byte[] blockMemory;
  readonly int blockStart;
  readonly int[] slots;       // triangle handle → block·4 + lane
  readonly int triangles, binaryNodes;

  public int TriangleCount => triangles;

  public int NodeCount => binaryNodes;

  /// <summary>Nodes of the eight-wide tree the queries walk.</summary>
  public int WideNodeCount => nodeCount;

  /// <summary>Triangle blocks stored: each leaf's from a new block, so the sum of the leaves' blocks.</summary>
  internal int BlockCount => (blockMemory.Length - Line) / Unsafe.SizeOf<TriangleBlock>();

  /// <summary>Size of the mesh's box (for relative tolerances).</summary>
  public double Extent { get; }

  public MeshBvh(SceneBrep mesh)
  {
    int n = triangles = mesh.Triangles;
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

    Bvh tree = Bvh.Build(boxes, centroids, order, BvhShape.Triangles);
    ArrayPool<Aabb>.Shared.Return(boxes);
    ArrayPool<Vector3d>.Shared.Return(centroids);
    binaryNodes = tree.Nodes.Length;
    root = tree.Nodes[0];
    // The child-box padding lies far above rounding (of box and triangle arithmetic, also far from the
    // origin) and far below any feature: the two-box test may then only keep more boxes, never fewer.
    // The root box is the union of every triangle's box.
    Aabb rootBox = n > 0 ? new Aabb(new Vector3d(root.MinX, root.MinY, root.MinZ), new Vector3d(root.MaxX, root.MaxY, root.MaxZ)) : Aabb.Empty;
    Extent = n > 0 ? (rootBox.Max - rootBox.Min).Length : 0.0;
    double magnitude = 0.0;
    for (int axis = 0; axis < 3 && n > 0; axis++)
      magnitude = Math.Max(magnitude, Math.Max(Math.Abs(rootBox.Min[axis]), Math.Abs(rootBox.Max[axis])));
    double pad = 1e-9 * (Extent + magnitude);
    MeshNode[] nodes = MeshCollapse.Collapse(tree, BvhShape.Triangles, pad, out stackSize);
    (blockMemory, blockStart, slots) = Store(mesh, nodes, order);
    nodeCount = nodes.Length;
    (nodeMemory, nodeStart) = Aligned(nodes);
    // Every float box lies in the root's (boxes nest; outward rounding is monotone): its coordinates bound them all.
    mx = Magnitude(root.MinX - pad, root.MaxX + pad);
    my = Magnitude(root.MinY - pad, root.MaxY + pad);
    mz = Magnitude(root.MinZ - pad, root.MaxZ + pad);
  }

  const int Line = 64;

  // The walks keep their stacks in fixed buffers of their frame, not in stackalloc memory: the runtime compiles a method
  // that uses stackalloc once, at its first call, optimized but without a profile (it cannot patch such a method while
  // it runs), and without the profile the walks' triangle test spilled its temporaries to the stack. With fixed buffers
  // the walks tier up as other methods do: their first calls run unoptimized code (the process's first ~100,000 queries
  // take about twice as long), and the final code, compiled with the profile, keeps the test in registers: 4–16 % less
  // time per query after that (docs/performance.md, "Against Intel Embree"). The limits are those the stackalloc buffers
  // had; deeper trees (a degenerate mesh's) get heap arrays, as before.
  internal const int FrameEntries = 1024, FrameSpanEntries = 512;

  [InlineArray(FrameEntries)]
  struct FrameInts
  {
    int item;
  }

  [InlineArray(FrameEntries)]
  struct FrameFloats
  {
    float item;
  }

  [InlineArray(FrameSpanEntries)]
  struct FrameSpans
  {
    NodeSpan item;
  }

  /// <summary>
  /// Pinned memory for <paramref name="count"/> items of <typeparamref name="T"/> from a 64-byte boundary on (a managed
  /// array is only 8-byte aligned): the buffer and the offset of the first item.
  /// </summary>
  static (byte[] Memory, int Start) AlignedBuffer<T>(int count) where T : struct
  {
    byte[] memory = GC.AllocateUninitializedArray<byte>(count * Unsafe.SizeOf<T>() + Line, pinned: true);   // never moved
    unsafe
    {
      fixed (byte* p = memory)
        return (memory, (int)((Line - (nint)p % Line) % Line));
    }
  }

  /// <summary>The items of an <see cref="AlignedBuffer{T}"/>.</summary>
  static Span<T> Items<T>(byte[] memory, int start, int count) where T : struct =>
    MemoryMarshal.Cast<byte, T>(memory.AsSpan(start, count * Unsafe.SizeOf<T>()));

  static (byte[] Memory, int Start) Aligned<T>(T[] items) where T : struct
  {
    (byte[] memory, int start) = AlignedBuffer<T>(items.Length);
    items.AsSpan().CopyTo(Items<T>(memory, start, items.Length));
    return (memory, start);
  }

  /// <summary>The first node (the root); node i is <c>Unsafe.Add(ref FirstNode(), i)</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  ref MeshNode FirstNode() => ref Unsafe.As<byte, MeshNode>(ref nodeMemory[nodeStart]);

  /// <summary>The first triangle block; block i is <c>Unsafe.Add(ref FirstBlock(), i)</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  ref TriangleBlock FirstBlock() => ref Unsafe.As<byte, TriangleBlock>(ref blockMemory[blockStart]);

  /// <summary>Where the first block lies in its cache line (0: on a line, as the walks' prefetch of three lines assumes).</summary>
  internal unsafe int FirstBlockLineOffset => (int)((nint)Unsafe.AsPointer(ref FirstBlock()) % Line);

  // The largest |coordinate| of the float slab [min, max] rounded outward (+∞ when it leaves the float range or is NaN).
  static double Magnitude(double min, double max)
  {
    double m = Math.Max(Math.Abs((double)MeshNode.Down(min)), Math.Abs((double)MeshNode.Up(max)));
    return double.IsFinite(m) ? m : double.PositiveInfinity;
  }

  /// <summary>
  /// The triangles in blocks of four, each leaf's from a new block in leaf order, written straight into their aligned
  /// buffer; the wide leaf lanes are pointed at their first block; and each triangle's place (block·4 + lane).
  /// </summary>
  static (byte[] Memory, int Start, int[] Slots) Store(SceneBrep mesh, MeshNode[] nodes, int[] order)
  {
    int n = order.Length;
    // Leaves cover [0, n) in leaf order without overlap: a leaf is known by its first item.
    int[] countAt = ArrayPool<int>.Shared.Rent(n + 1);
    Array.Clear(countAt, 0, n + 1);
    foreach (ref readonly MeshNode node in nodes.AsSpan())
      for (int lane = 0; lane < MeshNode.Width; lane++)
        if (node.Count[lane] > 0)
          countAt[node.Index[lane]] = node.Count[lane];
    // Each item's place (block · 4 + lane); countAt becomes each leaf's first block.
    int[] place = ArrayPool<int>.Shared.Rent(n);
    int used = 0;
    for (int i = 0; i < n;)
    {
      int count = countAt[i];
      for (int j = 0; j < count; j++)
        place[i + j] = TriangleBlock.Width * used + j;
      countAt[i] = used;
      used += (count + TriangleBlock.Width - 1) / TriangleBlock.Width;
      i += Math.Max(count, 1);
    }
    foreach (ref MeshNode node in nodes.AsSpan())
      for (int lane = 0; lane < MeshNode.Width; lane++)
        if (node.Count[lane] > 0)
        {
          node.Index[lane] = countAt[node.Index[lane]];
          node.Count[lane] = (node.Count[lane] + TriangleBlock.Width - 1) / TriangleBlock.Width;
        }

    (byte[] memory, int first) = AlignedBuffer<TriangleBlock>(used);
    var slots = new int[n];
    foreach (ref TriangleBlock block in Items<TriangleBlock>(memory, first, used))
      block.Clear();
    InChunks(n, (start, end) =>
    {
      Span<TriangleBlock> blocks = Items<TriangleBlock>(memory, first, used);
      for (int k = start; k < end; k++)
      {
        // The vertices again from the mesh (cheap) rather than three more large arrays for the collector.
        mesh.GetTriangleVertices(order[k], out Vector3 pa, out Vector3 pb, out Vector3 pc);
        int p = place[k];
        blocks[p / TriangleBlock.Width].Set(p % TriangleBlock.Width, order[k], pa, pb, pc);
        slots[order[k]] = p;
      }
    });
    ArrayPool<int>.Shared.Return(countAt);
    ArrayPool<int>.Shared.Return(place);
    return (memory, first, slots);
  }

  /// <summary>
  /// The vertices of triangle <paramref name="triangle"/> as its leaf block keeps them: the mesh's floats, widened (so
  /// the same doubles as <see cref="SceneBrep.GetVertex"/> converted). A hit's block has just been read by the query, so
  /// this is one load of the triangle's place instead of the mesh's index and three vertex loads.
  /// </summary>
  public void Vertices(int triangle, out Vector3d a, out Vector3d b, out Vector3d c)
  {
    int slot = slots[triangle];
    ref readonly TriangleBlock k = ref Unsafe.Add(ref FirstBlock(), slot / TriangleBlock.Width);
    int lane = slot % TriangleBlock.Width;
    a = new Vector3d(k.Ax.GetElement(lane), k.Ay.GetElement(lane), k.Az.GetElement(lane));
    b = new Vector3d(k.Bx.GetElement(lane), k.By.GetElement(lane), k.Bz.GetElement(lane));
    c = new Vector3d(k.Cx.GetElement(lane), k.Cy.GetElement(lane), k.Cz.GetElement(lane));
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

  /// <summary>Appends all hits of the line <c>p0 + t p1</c> (any t) to <paramref name="hits"/>, unsorted.</summary>
  [SkipLocalsInit]   // the float step (300 bytes) is written before it is read
  public void IntersectAll(Vector3d p0, Vector3d p1, List<MeshHit> hits)
  {
    if (!Start(p0, p1, out MeshLine line, out _, out _))
      return;
    if (FloatStep.Bounded(line, mx, my, mz))
      IntersectAll(new FloatStep(line, mx, my, mz), line, hits);
    else
      IntersectAll(new DoubleStep(line), line, hits);
  }

  [SkipLocalsInit]   // the stack is written before it is read
  void IntersectAll<TStep>(in TStep step, in MeshLine line, List<MeshHit> hits) where TStep : struct, IMeshBoxStep
  {
    Vector256<double> vox = Vector256.Create(line.Ox), voy = Vector256.Create(line.Oy), voz = Vector256.Create(line.Oz);
    Vector256<double> vdx = Vector256.Create(line.Dx), vdy = Vector256.Create(line.Dy), vdz = Vector256.Create(line.Dz);
    ref MeshNode nodes = ref FirstNode();
    ref TriangleBlock blocks = ref FirstBlock();

    // Entries as in Nearest; every box the line crosses (any t) is opened.
    Unsafe.SkipInit(out FrameInts frameInts);
    Span<int> stack = stackSize <= FrameEntries ? frameInts : new int[stackSize];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0)
    {
      int code = stack[--sp];
      if (code >= 0)
      {
        ref MeshNode n = ref Unsafe.Add(ref nodes, code);
        for (int mask = step.Cross(in n, out _, out _); mask != 0; mask &= mask - 1)
        {
          int lane = System.Numerics.BitOperations.TrailingZeroCount(mask);
          stack[sp++] = n.Child(code, lane);
        }
        continue;
      }
      Leaf(ref nodes, code, out int block, out int end);
      for (; block < end; block++)
      {
        int mask = Unsafe.Add(ref blocks, block).Hit(vox, voy, voz, vdx, vdy, vdz, out Vector256<double> t, out Vector256<double> u,
                                     out Vector256<double> v, out Vector256<double> det);
        for (; mask != 0; mask &= mask - 1)
        {
          int lane = System.Numerics.BitOperations.TrailingZeroCount(mask);
          hits.Add(new MeshHit
          {
            T = t.GetElement(lane),
            Triangle = Unsafe.Add(ref blocks, block).Id[lane],
            U = u.GetElement(lane),
            V = v.GetElement(lane),
            Front = det.GetElement(lane) > 0.0,
          });
        }
      }
    }
  }

  /// <summary>
  /// The per-ray set-up every walk shares: the line with its inverse direction, and its parameter interval in the box
  /// around every triangle (rounded outward to floats); false when there is nothing to find.
  /// </summary>
  bool Start(in Vector3d p0, in Vector3d p1, out MeshLine line, out float near, out float far)
  {
    line = new MeshLine(p0.X, p0.Y, p0.Z, p1.X, p1.Y, p1.Z);
    near = far = 0f;
    if (triangles == 0 || !LineBox(root, line, out double tMin, out double tMax))
      return false;
    near = MeshNode.Down(tMin);
    far = MeshNode.Up(tMax);
    return true;
  }

  /// <summary>The blocks [<paramref name="block"/>, <paramref name="end"/>) of the leaf a stack entry ~(node·8 + lane) names.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static void Leaf(ref MeshNode nodes, int code, out int block, out int end)
  {
    int slot = ~code;   // ≥ 0
    ref MeshNode parent = ref Unsafe.Add(ref nodes, slot >> 3);
    block = parent.Index[slot & 7];
    end = block + parent.Count[slot & 7];
  }

  /// <summary>
  /// Parameter interval of the line in the box around every triangle, the three slabs at once: per axis t0 = (min − o)·inv
  /// and t1 = (max − o)·inv, ordered (no swap when either is NaN), each widened by 1e-12·(|t0| + |t1|) so that hits on box
  /// faces (flat boxes) are not lost to rounding; an axis the line runs parallel to (d = 0) keeps the whole line when the
  /// origin lies within the slab and nothing otherwise. The interval is the intersection (a NaN end leaves it empty).
  /// Branch-free: which way a slab faces is a coin toss per ray for incoherent rays.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal static bool LineBox(in BvhNode root, in MeshLine l, out double tMin, out double tMax)
  {
    // The fourth lane's slab (−∞, +∞) never restricts the line.
    Vector256<double> o = Vector256.Create(l.Ox, l.Oy, l.Oz, 0.0), d = Vector256.Create(l.Dx, l.Dy, l.Dz, 1.0);
    Vector256<double> inv = Vector256.Create(l.Ix, l.Iy, l.Iz, 1.0);
    Vector256<double> min = Vector256.Create(root.MinX, root.MinY, root.MinZ, double.NegativeInfinity);
    Vector256<double> max = Vector256.Create(root.MaxX, root.MaxY, root.MaxZ, double.PositiveInfinity);
    Vector256<double> t0 = (min - o) * inv, t1 = (max - o) * inv;
    Vector256<double> swap = Vector256.GreaterThan(t0, t1);
    Vector256<double> a = Vector256.ConditionalSelect(swap, t1, t0), b = Vector256.ConditionalSelect(swap, t0, t1);
    Vector256<double> pad = Vector256.Create(1e-12) * (Vector256.Abs(a) + Vector256.Abs(b));
    a -= pad;
    b += pad;
    Vector256<double> parallel = Vector256.Equals(d, Vector256<double>.Zero);
    Vector256<double> within = Vector256.GreaterThanOrEqual(o, min) & Vector256.LessThanOrEqual(o, max);
    Vector256<double> inf = Vector256.Create(double.PositiveInfinity);
    a = Vector256.ConditionalSelect(parallel, Vector256.ConditionalSelect(within, -inf, inf), a);
    b = Vector256.ConditionalSelect(parallel, Vector256.ConditionalSelect(within, inf, -inf), b);
    // Max and Min as Math.Max and Math.Min (NaN wins, −0 < +0), so the order of the axes does not matter.
    Vector128<double> a2 = Vector128.Max(a.GetLower(), a.GetUpper()), b2 = Vector128.Min(b.GetLower(), b.GetUpper());
    tMin = Math.Max(a2.GetElement(0), a2.GetElement(1));
    tMax = Math.Min(b2.GetElement(0), b2.GetElement(1));
    return tMin <= tMax;
  }
}
