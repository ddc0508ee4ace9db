using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>The closest-record search of a <see cref="PreparedScene"/>: the BVH walk and the test of one member.</summary>
public sealed partial class PreparedScene
{
  /// <summary>Closest first-valid record over all members; false when the fast rule does not apply.</summary>
  /// <remarks>
  /// The answer does not depend on the order members are tested in (T decides, then the member index; a member is
  /// skipped only when it can neither win nor contain the origin). Bounded members go before the rectangles: a hit
  /// on one of them lets the rectangle cull dismiss the walls behind it without their exact test.
  /// </remarks>
  bool Closest(ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    if (always.Length > 0 && !Open(ref q, ref list, p0, p1))
      return false;
    if (bvh != null && !Bounded(ref q, ref list, p0, p1))
      return false;
    if (spheres != null && !Balls(ref q, ref list, p0, p1))
      return false;
    return rectangles == null || Rectangles(ref q, ref list, p0, p1);
  }

  /// <summary>The closed members of a small scene (balls), four at a time; only those the cull cannot dismiss are tested.</summary>
  /// <remarks>
  /// Optimized at its first call: its 256-bit vectors keep it out of a ReadyToRun image, so a render's first rays would run
  /// it as tier-0 code, calling the cull and the span accessors of its group array for every ray.
  /// </remarks>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  bool Balls(ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    Vector256<double> vox = Vector256.Create(p0.X), voy = Vector256.Create(p0.Y), voz = Vector256.Create(p0.Z);
    Vector256<double> vdx = Vector256.Create(p1.X), vdy = Vector256.Create(p1.Y), vdz = Vector256.Create(p1.Z);
    ReadOnlySpan<SphereCull.Group> groups = spheres!.Groups;
    for (int g = 0; g < groups.Length; g++)
    {
      ref readonly SphereCull.Group group = ref groups[g];
      for (int mask = SphereCull.MustTest(group, vox, voy, voz, vdx, vdy, vdz, q.Len2, q.BestT); mask != 0; mask &= mask - 1)
        if (!TestMember(group.Member[BitOperations.TrailingZeroCount(mask)], ref q, ref list, p0, p1))
          return false;
    }
    return true;
  }

  /// <summary>The open members other than the culled rectangles, each tested unless its line box is missed.</summary>
  bool Open(ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    // The whole-line test of a bounded plane needs every slab: a zero component would turn one into a half-line.
    // The reciprocals only when some member has a line box (an infinite plane has none).
    bool lineCull = lineBoxes && p1.X != 0.0 && p1.Y != 0.0 && p1.Z != 0.0;
    double ix = 0.0, iy = 0.0, iz = 0.0;
    if (lineCull)
    {
      ix = 1.0 / p1.X;
      iy = 1.0 / p1.Y;
      iz = 1.0 / p1.Z;
    }
    for (int k = 0; k < always.Length; k++)
    {
      int item = always[k];
      if (lineCull && members[item].HasLineBox && LineMisses(members[item].LineBox, p0.X, p0.Y, p0.Z, ix, iy, iz))
        continue;
      // A plane the ray leaves upwards (from above it, or from on it) has nothing to report (exact: conservative).
      if (members[item].HasPlaneZ && PlaneCull.Leaves(members[item], p0, p1, q.Len2))
        continue;
      if (!TestMember(item, ref q, ref list, p0, p1))
        return false;
    }
    return true;
  }

  /// <summary>The rectangles, four at a time in world space; only those the estimate cannot dismiss go through their chain.</summary>
  bool Rectangles(ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    Vector256<double> vox = Vector256.Create(p0.X), voy = Vector256.Create(p0.Y), voz = Vector256.Create(p0.Z);
    Vector256<double> vdx = Vector256.Create(p1.X), vdy = Vector256.Create(p1.Y), vdz = Vector256.Create(p1.Z);
    double scale = Math.Max(1.0, Math.Max(Math.Abs(p0.X), Math.Max(Math.Abs(p0.Y), Math.Abs(p0.Z))));
    double dirScale = Math.Max(Math.Abs(p1.X), Math.Max(Math.Abs(p1.Y), Math.Abs(p1.Z)));
    double accept = Intersection.RAY_EPSILON / Math.Sqrt(q.Len2);
    ReadOnlySpan<RectangleCull.Group> groups = rectangles!.Groups;
    for (int g = 0; g < groups.Length; g++)
    {
      ref readonly RectangleCull.Group group = ref groups[g];
      for (int mask = RectangleCull.MustTest(group, vox, voy, voz, vdx, vdy, vdz, scale, dirScale, accept, q.BestT); mask != 0; mask &= mask - 1)
        if (!TestMember(group.Member[BitOperations.TrailingZeroCount(mask)], ref q, ref list, p0, p1))
          return false;
    }
    return true;
  }

  /// <summary>The closed members, through the BVH.</summary>
  /// <remarks>The traversal stack is written before it is read: no zeroing of it per ray.</remarks>
  [SkipLocalsInit]
  bool Bounded(ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    // Zero direction components become tiny ones: no NaN from 0 · ∞ in the slab test, and the
    // padded boxes absorb the difference.
    double dx = p1.X == 0.0 ? 1e-300 : p1.X, dy = p1.Y == 0.0 ? 1e-300 : p1.Y, dz = p1.Z == 0.0 ? 1e-300 : p1.Z;
    double ix = 1.0 / dx, iy = 1.0 / dy, iz = 1.0 / dz;
    double ox = p0.X, oy = p0.Y, oz = p0.Z;
    WideBvh bvh = this.bvh!;

    // Most rays of a small scene miss all of its closed members: one scalar box test, before any set-up.
    if (!WideNode.Slab(bvh.Root, ox, oy, oz, ix, iy, iz, q.BestT, out _))
      return true;
    WideNode[] nodes = bvh.Nodes;
    int[] items = bvh.Items;
    Vector256<double> vox = Vector256.Create(ox), voy = Vector256.Create(oy), voz = Vector256.Create(oz);
    Vector256<double> vix = Vector256.Create(ix), viy = Vector256.Create(iy), viz = Vector256.Create(iz);

    // Visit boxes overlapping [0, best]; "≤ best" keeps equal-T ties for the depth-first order rule (the winner is
    // chosen by T, then member index, whatever the visiting order). Stack entries: an inner node (≥ 0) or a leaf lane
    // (~(node·4 + lane)), with the entry t of its box, re-checked against the shrinking best when popped.
    int size = bvh.StackSize;
    // In the frame (not zeroed) up to a tree depth of about 80, beyond any SAH tree of scene members; fixed buffers
    // rather than stackalloc, whose dynamic frame costs every call (see WalkStack).
    Unsafe.SkipInit(out WalkStack<int> ints);
    Unsafe.SkipInit(out WalkStack<double> times);
    Span<int> stack = size <= WalkStack<int>.Capacity ? ints : new int[size];
    Span<double> stackT = size <= WalkStack<double>.Capacity ? times : new double[size];
    int sp = 0;
    int code = 0;
    while (true)
    {
      if (code >= 0)
      {
        // Four child boxes at once; the hit ones are pushed nearest last, so the nearest is popped next.
        ref WideNode n = ref nodes[code];
        int hit = n.Hit(vox, voy, voz, vix, viy, viz, q.BestT, out Vector256<double> entry);
        int first = sp;
        for (; hit != 0; hit &= hit - 1)
        {
          int lane = BitOperations.TrailingZeroCount(hit);
          double t = entry.GetElement(lane);
          int c = n.Count[lane] == 0 ? n.Index[lane] : ~(code * WideNode.Width + lane);
          // Insertion into the pushed run, farthest first.
          int k = sp++;
          for (; k > first && stackT[k - 1] < t; k--)
          {
            stackT[k] = stackT[k - 1];
            stack[k] = stack[k - 1];
          }
          stackT[k] = t;
          stack[k] = c;
        }
      }
      else
      {
        int slot = ~code;
        ref WideNode parent = ref nodes[slot / WideNode.Width];
        int start = parent.Index[slot % WideNode.Width], end = start + parent.Count[slot % WideNode.Width];
        for (int k = start; k < end; k++)
        {
          int item = items[k];
          // A clear miss of the member's world bounding sphere skips its transform chain (exact: conservative).
          if (members[item].CullRadius2 > 0.0 && MissesSphere(members[item], p0, p1))
            continue;
          if (!TestMember(item, ref q, ref list, p0, p1))
            return false;
        }
      }
      while (true)
      {
        if (sp == 0)
          return true;
        --sp;
        if (stackT[sp] <= q.BestT)
          break;
      }
      code = stack[sp];
    }
  }

  /// <summary>True when the whole line (every t, negative ones too) misses the box.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static bool LineMisses(in Aabb box, double ox, double oy, double oz, double ix, double iy, double iz)
  {
    double ax = (box.Min.X - ox) * ix, bx = (box.Max.X - ox) * ix;
    double ay = (box.Min.Y - oy) * iy, by = (box.Max.Y - oy) * iy;
    double az = (box.Min.Z - oz) * iz, bz = (box.Max.Z - oz) * iz;
    double near = Math.Max(Math.Max(Math.Min(ax, bx), Math.Min(ay, by)), Math.Min(az, bz));
    double far = Math.Min(Math.Min(Math.Max(ax, bx), Math.Max(ay, by)), Math.Max(az, bz));
    // Each t carries a relative rounding error of a few ulps: only a clear gap is a miss.
    return near - far > 1.0e-12 * (Math.Abs(near) + Math.Abs(far));
  }

  /// <summary>True when the line misses the member's (enlarged) world bounding sphere: it has no records.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static bool MissesSphere(in PreparedMember m, in Vector3d p0, in Vector3d p1)
  {
    // Squared distance of the centre from the line: |oc|² − (oc·d)²/|d|² > r².
    double ox = m.CullCenter.X - p0.X, oy = m.CullCenter.Y - p0.Y, oz = m.CullCenter.Z - p0.Z;
    double od = ox * p1.X + oy * p1.Y + oz * p1.Z;
    double dd = p1.X * p1.X + p1.Y * p1.Y + p1.Z * p1.Z;
    double oo = ox * ox + oy * oy + oz * oz;
    return (oo - m.CullRadius2) * dd > od * od;
  }

  /// <summary>Tests one member; false when the fast rule does not apply to this ray.</summary>
  bool TestMember(int index, ref Query q, ref Intersection? list, in Vector3d p0, in Vector3d p1)
  {
    ref PreparedMember m = ref members[index];
    Vector3d lp0 = p0, lp1 = p1;
    ToLocal(m, ref lp0, ref lp1);

    if (m.RecordSolid != null || m.Csg != null)
    {
      bool has;
      bool inside;
      int leaf = -1;
      // The kernel writes into the query's free slot; a winner takes the slot instead of a copy (a wide copy right
      // after the kernel's scalar stores would wait for them).
      ref SolidRecord h = ref q.Free;
      if (m.RecordSolid is IRecordSolid solid)
      {
        // The library's sphere, plane and mesh called by name (decided when the member was bound); a shadow query asks
        // the mesh for any blocker up to the bound, not the first record (see Occluded).
        has = LibraryTypes.First(m.Direct, solid, lp0, lp1, q.Len2, q.Any, q.BestT, out h, out inside);
        // An any-hit entry in the bound's slack beyond "not far" need not be the first: the list decides (rare).
        if (has && q.Any && m.Direct == DirectSolid.AnyHit && h.Enter && !inside && !NotFar(h.T, q.Len2))
          return false;
      }
      else
      {
        int status = m.Csg!.IntersectFirst(lp0, lp1, q.Len2, out h, out leaf, out inside);
        if (status < 0)
          return false;
        has = status > 0;
      }
      if (inside)
      {
        // The ray starts inside this member: fine while it is the only one and its first record is an exit.
        if (!has || h.Enter || q.InsideIndex >= 0)
          return false;
        q.InsideIndex = index;
        q.InsideLeaf = leaf;
        q.InsideT = h.T;
        q.TakeInside();
        if (h.T < q.BestT)
          q.BestT = h.T;
        return true;
      }
      if (has && !h.Enter)
        return false;
      if (has && (h.T < q.EntryT || (h.T == q.EntryT && index < q.BestIndex)))
      {
        q.EntryT = h.T;
        q.BestIndex = index;
        q.BestLeaf = leaf;
        q.TakeBest();
        list = null;
        if (h.T < q.BestT)
          q.BestT = h.T;
      }
      if (has && q.Any && NotFar(h.T, q.Len2))
      {
        // A blocker: from now on only members that may contain the origin matter.
        q.Found = true;
        if (q.AnyBound < q.BestT)
          q.BestT = q.AnyBound;
      }
      return true;
    }

    // A leaf answering through the LinkedList API (allocates; always correct).
    LinkedList<Intersection>? records = m.Node.Intersect(lp0, lp1);
    if (records == null || records.First == null)
      return true;
    bool state = !records.First.Value.Enter;
    foreach (Intersection i in records)
    {
      if (i.T > 0.0 && i.T * i.T * q.Len2 > Intersection.RAY_EPSILON2)
      {
        if (state || !i.Enter)
          return false;
        if (i.T < q.EntryT || (i.T == q.EntryT && index < q.BestIndex))
        {
          q.EntryT = i.T;
          if (i.T < q.BestT)
            q.BestT = i.T;
          q.BestIndex = index;
          q.BestLeaf = -1;
          list = i;
        }
        return true;
      }
      state = i.Enter;
    }
    return !state;
  }
}
