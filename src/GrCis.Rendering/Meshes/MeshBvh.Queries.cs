using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>The closest-hit walks of a <see cref="MeshBvh"/> (the any-hit walk: <c>MeshBvh.Any.cs</c>).</summary>
internal sealed partial class MeshBvh
{
  /// <summary>
  /// An upper bound on the T of every hit <see cref="Intersection.FirstIntersection"/> rejects: those have
  /// T ≤ sqrt(RAY_EPSILON2 / len2) up to rounding (the exact test decides which they are).
  /// </summary>
  public static double RejectLimit(double len2)
  {
    double limit = Math.Sqrt(Intersection.RAY_EPSILON2 / len2);
    return limit + (1e-9 * limit + 1e-300);
  }

  /// <summary>
  /// The first hit in the list's order (T, then triangle) among hits <see cref="Intersection.FirstIntersection"/>
  /// accepts (<c>T &gt; 0</c>, <c>T² len2 &gt; RAY_EPSILON2</c>) when <paramref name="accepted"/>, among those with
  /// T ≤ <paramref name="tMax"/>; otherwise the last hit in that order among those it rejects. Allocation-free, nearest
  /// boxes first, pruned by the best so far.
  /// </summary>
  [SkipLocalsInit]   // the float step (300 bytes) is written before it is read
  public bool Nearest(in Vector3d p0, in Vector3d p1, double len2, bool accepted, out MeshHit best, double tMax = double.PositiveInfinity)
  {
    best = default;
    if (!Start(p0, p1, out MeshLine line, out float near, out float far))
      return false;
    return FloatStep.Bounded(line, mx, my, mz)
      ? Nearest(new FloatStep(line, mx, my, mz), line, near, far, len2, accepted, out best, tMax)
      : Nearest(new DoubleStep(line), line, near, far, len2, accepted, out best, tMax);
  }

  [SkipLocalsInit]   // the stack is written before it is read: no zeroing of it per query
  bool Nearest<TStep>(in TStep step, in MeshLine line, float rootNear, float rootFar, double len2, bool accepted,
                      out MeshHit best, double tMax) where TStep : struct, IMeshBoxStep
  {
    best = default;
    double limit = RejectLimit(len2);
    bool found = false;
    // Accepted: boxes beyond tMax are never opened, hits beyond it never taken.
    double bestT = accepted ? tMax : double.NegativeInfinity;
    int bestTri = 0;
    Vector256<double> vox = Vector256.Create(line.Ox), voy = Vector256.Create(line.Oy), voz = Vector256.Create(line.Oz);
    Vector256<double> vdx = Vector256.Create(line.Dx), vdy = Vector256.Create(line.Dy), vdz = Vector256.Create(line.Dz);
    Vector256<double> vlen2 = Vector256.Create(len2), eps2 = Vector256.Create(Intersection.RAY_EPSILON2), vtMax = Vector256.Create(tMax);
    // The float bounds of the boxes still worth opening (rounded outward: a box the double bounds keep is kept):
    // accepted T in (0, best], rejected T in [best, limit].
    Vector256<float> lo = Vector256.Create(accepted ? 0f : MeshNode.Down(bestT));
    Vector256<float> hi = Vector256.Create(MeshNode.Up(accepted ? bestT : limit));
    ref MeshNode nodes = ref FirstNode();
    ref TriangleBlock blocks = ref FirstBlock();

    // Each entry: an inner node (≥ 0) or a leaf lane (~(node·8 + lane)) and the line's parameter interval in its box,
    // re-checked against the best when popped; the root's interval is that of the whole mesh's box.
    // On the stack (not zeroed) up to a tree depth of about 70; only a degenerate mesh's tree is deeper.
    Unsafe.SkipInit(out FrameSpans frameSpans);
    Span<NodeSpan> stack = stackSize <= FrameSpanEntries ? frameSpans : new NodeSpan[stackSize];
    Unsafe.SkipInit(out Vector256<float> spillNear);
    Unsafe.SkipInit(out Vector256<float> spillFar);
    Unsafe.SkipInit(out Vector256<float> spillKey);
    Unsafe.SkipInit(out Vector256<int> spillCode);
    int sp = 0;
    stack[sp++] = new NodeSpan(0, rootNear, rootFar);
    while (sp > 0)
    {
      NodeSpan e = stack[--sp];
      if (accepted ? (e.Far <= 0.0 || e.Near > bestT) : (e.Near > limit || e.Far < bestT))
        continue;
      int code = e.Node;
    Open:
      if (code >= 0)
      {
        ref MeshNode n = ref Unsafe.Add(ref nodes, code);
        int mask = step.Cross(in n, out Vector256<float> near, out Vector256<float> far);
        mask &= accepted
          ? (int)(Vector256.GreaterThan(far, lo) & Vector256.LessThanOrEqual(near, hi)).ExtractMostSignificantBits()
          : (int)(Vector256.GreaterThanOrEqual(far, lo) & Vector256.LessThanOrEqual(near, hi)).ExtractMostSignificantBits();
        if (mask != 0 && (mask & (mask - 1)) == 0)
        {
          // One box left: opened at once, not pushed and popped (it met the bounds just now).
          int only = BitOperations.TrailingZeroCount(mask);
          code = n.Child(code, only);
          goto Open;
        }
        if (mask == 0)
          continue;
        // The boxes more likely to hold the answer are popped first: nearest entry for the first accepted hit,
        // farthest exit for the last rejected one. The most likely is opened at once (it met the bounds just now),
        // the others pushed, most likely last; their memory is prefetched while this subtree is walked. The lanes
        // are spilled once and read from memory (an element read by a variable lane spills the vector each time).
        spillNear = near;
        spillFar = far;
        spillKey = accepted ? near : -far;
        spillCode = n.Children(code);
        for (int m = mask; m != 0; m &= m - 1)
          Prefetch(ref nodes, ref blocks, Lane(ref spillCode, BitOperations.TrailingZeroCount(m)));
        code = PushOrdered(stack, ref sp, mask, ref spillCode, ref spillNear, ref spillFar, ref spillKey,
                           accepted ? SpanOrder.Near : SpanOrder.FarDescending);
        goto Open;
      }
      Leaf(ref nodes, code, out int block, out int end);
      for (; block < end; block++)
      {
        int mask = Unsafe.Add(ref blocks, block).Hit(vox, voy, voz, vdx, vdy, vdz, out Vector256<double> t, out Vector256<double> u,
                                     out Vector256<double> v, out Vector256<double> det);
        if (mask == 0)
          continue;
        // Intersection.FirstIntersection's rule, per lane: (t > 0) and (t · t) · len2 > RAY_EPSILON2.
        int valid = (int)(Vector256.GreaterThan(t, Vector256<double>.Zero) & Vector256.GreaterThan(t * t * vlen2, eps2)).ExtractMostSignificantBits();
        if (accepted)
          valid &= (int)Vector256.LessThanOrEqual(t, vtMax).ExtractMostSignificantBits();
        for (mask &= accepted ? valid : ~valid; mask != 0; mask &= mask - 1)
        {
          int lane = BitOperations.TrailingZeroCount(mask);
          double tl = t.GetElement(lane);
          int id = Unsafe.Add(ref blocks, block).Id[lane];
          bool better = accepted
            ? tl < bestT || (tl == bestT && id < bestTri)
            : tl > bestT || (tl == bestT && id > bestTri);
          if (!found || better)
          {
            found = true;
            bestT = tl;
            bestTri = id;
            best = new MeshHit { T = tl, Triangle = id, U = u.GetElement(lane), V = v.GetElement(lane), Front = det.GetElement(lane) > 0.0 };
            if (accepted)
              hi = Vector256.Create(MeshNode.Up(bestT));
            else
              lo = Vector256.Create(MeshNode.Down(bestT));
          }
        }
      }
    }
    return found;
  }

  /// <summary>
  /// <see cref="Nearest"/>'s two answers from one walk: the first accepted hit (<paramref name="first"/>) and the last
  /// rejected one (<paramref name="last"/>). A box is opened while it may hold either; the one nearer the origin (in
  /// front or behind) is opened first. Boxes and triangles around the origin, which both searches need, are visited once.
  /// </summary>
  [SkipLocalsInit]   // the float step (300 bytes) is written before it is read
  public void NearestBoth(in Vector3d p0, in Vector3d p1, double len2, out bool hasFirst, out MeshHit first, out bool hasLast, out MeshHit last)
  {
    first = last = default;
    hasFirst = hasLast = false;
    if (!Start(p0, p1, out MeshLine line, out float near, out float far))
      return;
    if (near > RejectLimit(len2))
    {
      // Every hit lies at T ≥ the box's entry > the limit: all are accepted and there is no last rejected one, so the
      // first is Nearest's (the least T, then triangle, whatever the walk): a ray from outside, ahead of the mesh.
      hasFirst = FloatStep.Bounded(line, mx, my, mz)
        ? Nearest(new FloatStep(line, mx, my, mz), line, near, far, len2, true, out first, double.PositiveInfinity)
        : Nearest(new DoubleStep(line), line, near, far, len2, true, out first, double.PositiveInfinity);
      return;
    }
    if (FloatStep.Bounded(line, mx, my, mz))
      NearestBoth(new FloatStep(line, mx, my, mz), line, near, far, len2, out hasFirst, out first, out hasLast, out last);
    else
      NearestBoth(new DoubleStep(line), line, near, far, len2, out hasFirst, out first, out hasLast, out last);
  }

  [SkipLocalsInit]   // the stack is written before it is read
  void NearestBoth<TStep>(in TStep step, in MeshLine line, float rootNear, float rootFar, double len2,
                          out bool hasFirst, out MeshHit first, out bool hasLast, out MeshHit last) where TStep : struct, IMeshBoxStep
  {
    first = last = default;
    hasFirst = hasLast = false;
    double limit = RejectLimit(len2);
    double bestF = double.PositiveInfinity, bestB = double.NegativeInfinity;
    int triF = 0, triB = 0;
    Vector256<double> vox = Vector256.Create(line.Ox), voy = Vector256.Create(line.Oy), voz = Vector256.Create(line.Oz);
    Vector256<double> vdx = Vector256.Create(line.Dx), vdy = Vector256.Create(line.Dy), vdz = Vector256.Create(line.Dz);
    Vector256<double> vlen2 = Vector256.Create(len2), eps2 = Vector256.Create(Intersection.RAY_EPSILON2);
    // Float bounds rounded outward, as in Nearest.
    Vector256<float> hiF = Vector256.Create(float.PositiveInfinity), loB = Vector256.Create(float.NegativeInfinity);
    Vector256<float> vlimit = Vector256.Create(MeshNode.Up(limit));
    ref MeshNode nodes = ref FirstNode();
    ref TriangleBlock blocks = ref FirstBlock();

    Unsafe.SkipInit(out FrameSpans frameSpans);
    Span<NodeSpan> stack = stackSize <= FrameSpanEntries ? frameSpans : new NodeSpan[stackSize];
    Unsafe.SkipInit(out Vector256<float> spillNear);
    Unsafe.SkipInit(out Vector256<float> spillFar);
    Unsafe.SkipInit(out Vector256<float> spillKey);
    Unsafe.SkipInit(out Vector256<int> spillCode);
    int sp = 0;
    stack[sp++] = new NodeSpan(0, rootNear, rootFar);
    while (sp > 0)
    {
      NodeSpan e = stack[--sp];
      // Nearest's two tests: accepted T in (0, bestF], rejected T in [bestB, limit].
      if ((e.Far <= 0.0 || e.Near > bestF) && (e.Near > limit || e.Far < bestB))
        continue;
      int code = e.Node;
    Open:
      if (code >= 0)
      {
        ref MeshNode n = ref Unsafe.Add(ref nodes, code);
        int mask = step.Cross(in n, out Vector256<float> near, out Vector256<float> far);
        // Only boxes either search still needs; the rest would be dropped when popped.
        Vector256<float> zero = Vector256<float>.Zero;
        mask &= (int)((Vector256.GreaterThan(far, zero) & Vector256.LessThanOrEqual(near, hiF)) |
                      (Vector256.LessThanOrEqual(near, vlimit) & Vector256.GreaterThanOrEqual(far, loB))).ExtractMostSignificantBits();
        if (mask != 0 && (mask & (mask - 1)) == 0)
        {
          // One box left: opened at once (as in Nearest).
          int only = BitOperations.TrailingZeroCount(mask);
          code = n.Child(code, only);
          goto Open;
        }
        if (mask == 0)
          continue;
        // Distance from the origin along the line (negative for a box around it): the smallest is popped first; the
        // nearest opened at once, the others pushed and prefetched (as in Nearest).
        spillNear = near;
        spillFar = far;
        spillKey = Vector256.MaxNative(near, -far);
        spillCode = n.Children(code);
        for (int m = mask; m != 0; m &= m - 1)
          Prefetch(ref nodes, ref blocks, Lane(ref spillCode, BitOperations.TrailingZeroCount(m)));
        code = PushOrdered(stack, ref sp, mask, ref spillCode, ref spillNear, ref spillFar, ref spillKey, SpanOrder.NearerEnd);
        goto Open;
      }
      Leaf(ref nodes, code, out int block, out int end);
      for (; block < end; block++)
      {
        int mask = Unsafe.Add(ref blocks, block).Hit(vox, voy, voz, vdx, vdy, vdz, out Vector256<double> t, out Vector256<double> u,
                                     out Vector256<double> v, out Vector256<double> det);
        if (mask == 0)
          continue;
        int valid = (int)(Vector256.GreaterThan(t, Vector256<double>.Zero) & Vector256.GreaterThan(t * t * vlen2, eps2)).ExtractMostSignificantBits();
        for (; mask != 0; mask &= mask - 1)
        {
          int lane = BitOperations.TrailingZeroCount(mask);
          double tl = t.GetElement(lane);
          int id = Unsafe.Add(ref blocks, block).Id[lane];
          if ((valid >> lane & 1) != 0)
          {
            if (!hasFirst || tl < bestF || (tl == bestF && id < triF))
            {
              hasFirst = true;
              bestF = tl;
              triF = id;
              hiF = Vector256.Create(MeshNode.Up(bestF));
              first = new MeshHit { T = tl, Triangle = id, U = u.GetElement(lane), V = v.GetElement(lane), Front = det.GetElement(lane) > 0.0 };
            }
          }
          else if (!hasLast || tl > bestB || (tl == bestB && id > triB))
          {
            hasLast = true;
            bestB = tl;
            triB = id;
            loB = Vector256.Create(MeshNode.Down(bestB));
            last = new MeshHit { T = tl, Triangle = id, U = u.GetElement(lane), V = v.GetElement(lane), Front = det.GetElement(lane) > 0.0 };
          }
        }
      }
    }
  }

  /// <summary>How a closest-hit walk orders the boxes it pushes: the least key is opened first.</summary>
  enum SpanOrder
  {
    /// <summary>Nearest entry first (the first accepted hit): key = near.</summary>
    Near,
    /// <summary>Farthest exit first (the last rejected hit): key = −far.</summary>
    FarDescending,
    /// <summary>The end nearer the origin first, in front or behind (both searches at once): key = max(near, −far).</summary>
    NearerEnd,
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static float Key(in NodeSpan e, SpanOrder order) =>
    order == SpanOrder.Near ? e.Near : order == SpanOrder.FarDescending ? -e.Far : MathF.Max(e.Near, -e.Far);

  /// <summary>
  /// A node's kept boxes (<paramref name="mask"/>, two or more lanes, their codes, near and far ends and keys spilled):
  /// returns the code of the box of least key, to be opened at once (it met the bounds just now), and pushes the others
  /// so that lesser keys are popped first (two boxes: one comparison; more: an insertion sort).
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static int PushOrdered(Span<NodeSpan> stack, ref int sp, int mask, ref Vector256<int> codes, ref Vector256<float> near,
                         ref Vector256<float> far, ref Vector256<float> key, SpanOrder order)
  {
    int a = BitOperations.TrailingZeroCount(mask);
    int rest = mask & (mask - 1);
    if ((rest & (rest - 1)) == 0)
    {
      // Two boxes (the most common case).
      int b = BitOperations.TrailingZeroCount(rest);
      if (Lane(ref key, b) < Lane(ref key, a))
        (a, b) = (b, a);
      stack[sp++] = new NodeSpan(Lane(ref codes, b), Lane(ref near, b), Lane(ref far, b));
      return Lane(ref codes, a);
    }
    int pushed = sp;
    for (; mask != 0; mask &= mask - 1)
    {
      int lane = BitOperations.TrailingZeroCount(mask);
      var s = new NodeSpan(Lane(ref codes, lane), Lane(ref near, lane), Lane(ref far, lane));
      float sk = Lane(ref key, lane);
      int k = sp++;
      for (; k > pushed && Key(stack[k - 1], order) < sk; k--)
        stack[k] = stack[k - 1];
      stack[k] = s;
    }
    return stack[--sp].Node;
  }

  /// <summary>Lane <paramref name="lane"/> of a spilled vector (one load, no bounds check: lane is 0…7).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static T Lane<T>(ref Vector256<T> v, int lane) => Unsafe.Add(ref Unsafe.As<Vector256<T>, T>(ref v), lane);

  /// <summary>
  /// A hint to bring the memory of a pushed entry into the cache while the walk goes on elsewhere: an inner node's
  /// three plane lines (what its box step reads), or a leaf's first triangle block (three lines from its 64-byte
  /// boundary). Issued for every kept box before the sort, the one opened at once included. No effect on any answer.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static unsafe void Prefetch(ref MeshNode nodes, ref TriangleBlock blocks, int code)
  {
    if (!Sse.IsSupported)
      return;
    byte* p;
    if (code >= 0)
      p = (byte*)Unsafe.AsPointer(ref Unsafe.Add(ref nodes, code));   // the node buffer is pinned
    else
    {
      Leaf(ref nodes, code, out int block, out _);
      p = (byte*)Unsafe.AsPointer(ref Unsafe.Add(ref blocks, block));   // pinned
    }
    Sse.Prefetch0(p);
    Sse.Prefetch0(p + 64);
    Sse.Prefetch0(p + 128);
  }

  /// <summary>A stack entry: node code and the line's parameter interval in its box (floats, rounded outward).</summary>
  readonly record struct NodeSpan(int Node, float Near, float Far);
}
