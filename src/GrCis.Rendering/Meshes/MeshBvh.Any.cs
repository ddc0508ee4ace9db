using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>The any-hit walk of a <see cref="MeshBvh"/>.</summary>
internal sealed partial class MeshBvh
{
  /// <summary>
  /// Any-hit with early exit, with a zone near the origin that must be clear: some hit that
  /// <see cref="Intersection.FirstIntersection"/> accepts with T in (<paramref name="zone"/>, <paramref name="tMax"/>] and,
  /// when <paramref name="frontOnly"/>, runs against the face (Front), while no accepted hit (either face) lies in
  /// (0, <paramref name="zone"/>] (0 ≤ zone ≤ tMax). An accepted hit in the zone stops the walk: false with
  /// <paramref name="inZone"/>. Otherwise true at a hit of the range found in no particular order once the zone is known
  /// clear (with a zone of 0, at once), or false, with <paramref name="onlyBack"/> true when accepted back-face hits (exits)
  /// lie in the range. Boxes beyond the bound or behind the origin are never opened.
  /// </summary>
  [SkipLocalsInit]   // the float step (300 bytes) is written before it is read
  public bool Any(in Vector3d p0, in Vector3d p1, double len2, double zone, double tMax, bool frontOnly, out MeshHit hit,
                  out bool inZone, out bool onlyBack)
  {
    hit = default;
    inZone = onlyBack = false;
    if (!Start(p0, p1, out MeshLine line, out float near, out float far) || far <= 0f || near > tMax)
      return false;
    return FloatStep.Bounded(line, mx, my, mz)
      ? Any(new FloatStep(line, mx, my, mz), line, near, len2, zone, tMax, frontOnly, out hit, out inZone, out onlyBack)
      : Any(new DoubleStep(line), line, near, len2, zone, tMax, frontOnly, out hit, out inZone, out onlyBack);
  }

  [SkipLocalsInit]   // the stack is written before it is read
  bool Any<TStep>(in TStep step, in MeshLine line, float rootNear, double len2, double zone, double tMax, bool frontOnly,
                  out MeshHit hit, out bool inZone, out bool onlyBack) where TStep : struct, IMeshBoxStep
  {
    hit = default;
    inZone = onlyBack = false;
    Vector256<double> vox = Vector256.Create(line.Ox), voy = Vector256.Create(line.Oy), voz = Vector256.Create(line.Oz);
    Vector256<double> vdx = Vector256.Create(line.Dx), vdy = Vector256.Create(line.Dy), vdz = Vector256.Create(line.Dz);
    Vector256<double> vlen2 = Vector256.Create(len2), eps2 = Vector256.Create(Intersection.RAY_EPSILON2);
    Vector256<double> vzone = Vector256.Create(zone);
    // The bound drops to the zone once a hit of the range is found: only the zone is searched after it. Its float form
    // is rounded up, so no box the double bound keeps is lost.
    double bound = tMax;
    float hiBound = MeshNode.Up(tMax);
    bool found = false;
    ref MeshNode nodes = ref FirstNode();
    ref TriangleBlock blocks = ref FirstBlock();

    // Entries as in Nearest: an inner node (≥ 0) or a leaf lane (~(node·8 + lane)) and the line's entry into its box,
    // re-checked against the bound when popped; only boxes meeting (0, bound] are pushed.
    Unsafe.SkipInit(out FrameInts frameInts);
    Unsafe.SkipInit(out FrameFloats frameFloats);
    Span<int> stack = stackSize <= FrameEntries ? frameInts : new int[stackSize];
    Span<float> stackNear = stackSize <= FrameEntries ? frameFloats : new float[stackSize];
    Unsafe.SkipInit(out Vector256<float> spillNear);
    Unsafe.SkipInit(out Vector256<int> spillCode);
    int sp = 0;
    stack[sp] = 0;
    stackNear[sp++] = rootNear;
    while (sp > 0)
    {
      --sp;
      if (stackNear[sp] > hiBound)
        continue;
      int code = stack[sp];
    Open:
      if (code >= 0)
      {
        ref MeshNode n = ref Unsafe.Add(ref nodes, code);
        int mask = step.Cross(in n, out Vector256<float> near, out Vector256<float> far);
        mask &= (int)(Vector256.GreaterThan(far, Vector256<float>.Zero) & Vector256.LessThanOrEqual(near, Vector256.Create(hiBound))).ExtractMostSignificantBits();
        if (mask != 0 && (mask & (mask - 1)) == 0)
        {
          // One box left: opened at once, as popping it right after its push would (the same bound).
          int only = BitOperations.TrailingZeroCount(mask);
          code = n.Child(code, only);
          goto Open;
        }
        if (mask == 0)
          continue;
        // In lane order: nearest first opened fewer boxes on segments (11.3 against 13.0 a ray) but measured slower on
        // shadow rays (3.71x against 3.43x Embree's time, bench/results/2026-12-06-occlusion.md). Lanes spilled once
        // and the pushed boxes prefetched, as in Nearest.
        spillNear = near;
        spillCode = n.Children(code);
        for (; mask != 0; mask &= mask - 1)
        {
          int lane = BitOperations.TrailingZeroCount(mask);
          int child = Lane(ref spillCode, lane);
          stack[sp] = child;
          stackNear[sp++] = Lane(ref spillNear, lane);
          Prefetch(ref nodes, ref blocks, child);
        }
        code = stack[--sp];   // the last pushed, at once, as the next pop would (the same bound)
        goto Open;
      }
      Leaf(ref nodes, code, out int block, out int end);
      for (; block < end; block++)
      {
        int mask = Unsafe.Add(ref blocks, block).Hit(vox, voy, voz, vdx, vdy, vdz, out Vector256<double> t, out Vector256<double> u,
                                     out Vector256<double> v, out Vector256<double> det);
        if (mask == 0)
          continue;
        // Accepted (as in Nearest) and not beyond the bound.
        mask &= (int)(Vector256.GreaterThan(t, Vector256<double>.Zero) & Vector256.GreaterThan(t * t * vlen2, eps2) &
                      Vector256.LessThanOrEqual(t, Vector256.Create(bound))).ExtractMostSignificantBits();
        if (mask == 0)
          continue;
        if ((mask & (int)Vector256.LessThanOrEqual(t, vzone).ExtractMostSignificantBits()) != 0)
        {
          inZone = true;
          onlyBack = false;
          return false;
        }
        // The first (front face) in triangle order is taken.
        int take = frontOnly ? mask & (int)Vector256.GreaterThan(det, Vector256<double>.Zero).ExtractMostSignificantBits() : mask;
        if (take == 0)
        {
          onlyBack = true;
          continue;
        }
        int lane = BitOperations.TrailingZeroCount(take);
        hit = new MeshHit { T = t.GetElement(lane), Triangle = Unsafe.Add(ref blocks, block).Id[lane], U = u.GetElement(lane), V = v.GetElement(lane), Front = det.GetElement(lane) > 0.0 };
        found = true;
        onlyBack = false;
        if (!(zone > 0.0))
          return true;
        bound = zone;
        hiBound = MeshNode.Up(zone);
      }
    }
    return found;
  }
}
