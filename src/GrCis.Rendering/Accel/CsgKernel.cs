using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// Allocation-free evaluation of a CSG subtree (any operations, nested) whose leaves are all solids with
/// <see cref="IRecordSolid.IntersectAll"/>: the same records, merged by the same rule, as
/// <see cref="CSGInnerNode.Intersect"/>, held in stack buffers instead of linked lists.
/// </summary>
/// <remarks>
/// Mirrors the list path step by step: each child gets the ray through its FromParent (identities
/// skipped, as the prepared scene does), children are folded left to right, a merge keeps a record only
/// where the combined inside state changes and overwrites its Enter (the list path mutates the shared
/// record), on a tie both operands advance and the left record represents them, an empty right operand of
/// union/xor/difference is skipped unmerged, and intersection/difference stop at an empty left operand.
/// Records live in one arena per query; lists are byte indices into it, so the Enter overwrite is seen by
/// every later merge exactly as the shared <see cref="Intersection"/> object would be.
/// </remarks>
internal sealed class CsgKernel
{
  /// <summary>Largest record count (sum of the leaves' <see cref="IRecordSolid.MaxRecords"/>) the kernel takes.</summary>
  public const int MaxTotalRecords = 64;

  /// <summary>Largest index workspace (bytes); deeper trees stay on the list path.</summary>
  const int MaxWork = 2048;

  struct Node
  {
    /// <summary>Leaf index (≥ 0) or -1 for an inner node.</summary>
    public int Leaf;

    /// <summary>Index into <see cref="steps"/> of this node's FromParent, -1 for identity (and the root).</summary>
    public int Step;

    /// <summary>Next sibling (-1: last child).</summary>
    public int Next;

    public int ChildCount;

    /// <summary>Upper bound on records of this subtree, and the index workspace its evaluation needs.</summary>
    public int Max, Work;

    /// <summary>Operation as a truth table: bit (left ? 2 : 0) | (right ? 1 : 0).</summary>
    public int Table;
    public bool ShortCircuit, Trivial;
  }

  readonly Node[] nodes;
  readonly Matrix4d[] steps;

  /// <summary>The leaves in depth-first order, with what completing their records needs (matrices, attributes).</summary>
  internal readonly PreparedMember[] Leaves;

  /// <summary>Upper bound on the records of one query.</summary>
  public int MaxRecords { get; }

  CsgKernel(Node[] nodes, Matrix4d[] steps, PreparedMember[] leaves)
  {
    this.nodes = nodes;
    this.steps = steps;
    Leaves = leaves;
    MaxRecords = nodes[0].Max;
  }

  // ---------------------------------------------------------------- compilation

  /// <summary>
  /// True when the list path must answer for <paramref name="root"/>: not a library CSG node, a bounding
  /// volume, a leaf without <see cref="IRecordSolid.IntersectAll"/> (meshes, script solids, Bézier patches,
  /// animated nodes), or more than <see cref="MaxTotalRecords"/> records.
  /// </summary>
  public static CsgKernel? TryCompile(ISceneNode root)
  {
    if (!IsLibraryCsg(root))
      return null;
    var nodes = new List<Node>();
    var steps = new List<Matrix4d>();
    var solids = new List<IRecordSolid>();
    if (Add(root, -1, nodes, steps, solids) < 0 || nodes[0].Max > MaxTotalRecords || nodes[0].Work > MaxWork)
      return null;

    var leaves = new PreparedMember[solids.Count];
    for (int i = 0; i < leaves.Length; i++)
    {
      leaves[i] = new PreparedMember { Node = solids[i], WorldBox = Aabb.Empty };
      PreparedScene.BindSolid(ref leaves[i], solids[i]);
    }
    return new CsgKernel(nodes.ToArray(), steps.ToArray(), leaves);
  }

  static bool IsLibraryCsg(ISceneNode node) => LibraryTypes.IsKernelCsg(node);

  /// <summary>Appends <paramref name="node"/>'s subtree in depth-first order; its index, or -1 when it cannot be compiled.</summary>
  static int Add(ISceneNode node, int step, List<Node> nodes, List<Matrix4d> steps, List<IRecordSolid> solids)
  {
    int index = nodes.Count;
    if (node is IRecordSolid f)
    {
      int max = f.RecordsMatchIntersect ? f.MaxRecords : -1;
      if (max <= 0)
        return -1;
      nodes.Add(new Node { Leaf = solids.Count, Step = step, Next = -1, Max = max });
      solids.Add(f);
      return index;
    }
    if (!IsLibraryCsg(node))
      return -1;

    var csg = (CSGInnerNode)node;
    int table = 0;
    for (int k = 0; k < 4; k++)
      if (csg.Result((k & 2) != 0, (k & 1) != 0))
        table |= 1 << k;
    nodes.Add(new Node
    {
      Leaf = -1,
      Step = step,
      Next = -1,
      Table = table,
      ShortCircuit = csg.shortCircuit,
      Trivial = csg.trivial,
    });

    int sum = 0, childWork = 0, previous = -1, count = 0;
    foreach (ISceneNode child in csg.Children)
    {
      Matrix4d m = child.FromParent;
      int childStep = -1;
      if (m != Matrix4d.Identity)
      {
        childStep = steps.Count;
        steps.Add(m);
      }
      int c = Add(child, childStep, nodes, steps, solids);
      if (c < 0)
        return -1;
      if (previous >= 0)
        nodes[previous] = nodes[previous] with { Next = c };
      previous = c;
      count++;
      sum += nodes[c].Max;
      childWork = Math.Max(childWork, nodes[c].Work);
      if (sum > MaxTotalRecords)
        return -1;
    }
    // Workspace: a child's list and a merge's output (each ≤ sum), then the child's own workspace.
    nodes[index] = nodes[index] with { ChildCount = count, Max = sum, Work = 2 * sum + childWork };
    return index;
  }

  // ---------------------------------------------------------------- queries

  /// <summary>
  /// The first record <see cref="Intersection.FirstIntersection"/> accepts from the subtree's list (local ray of
  /// the subtree's root), its leaf, and the CSG inside state before it (as <see cref="IRecordSolid.IntersectFirst"/>).
  /// Returns 1 (a record), 0 (none), or -1 when the list path must answer (a list it would not merge: NaN or
  /// infinite T).
  /// </summary>
  [SkipLocalsInit]
  public int IntersectFirst(in Vector3d p0, in Vector3d p1, double len2, out SolidRecord hit, out int leaf, out bool insideBefore)
  {
    hit = default;
    leaf = -1;
    insideBefore = false;
    int max = MaxRecords;
    Span<SolidRecord> arena = stackalloc SolidRecord[max];
    Span<byte> leafOf = stackalloc byte[max];
    Span<byte> list = stackalloc byte[max];
    Span<byte> work = stackalloc byte[nodes[0].Work];
    int used = 0;
    int n = Eval(0, p0, p1, arena, leafOf, ref used, list, work);
    if (n <= 0)
      return n;

    // The scan FirstIntersection does, tracking the state the skipped records leave.
    bool state = !arena[list[0]].Enter;
    for (int k = 0; k < n; k++)
    {
      ref SolidRecord r = ref arena[list[k]];
      if (r.T > 0.0 && r.T * r.T * len2 > Intersection.RAY_EPSILON2)
      {
        hit = r;
        leaf = leafOf[list[k]];
        insideBefore = state;
        return 1;
      }
      state = r.Enter;
    }
    insideBefore = state;
    return 0;
  }

  /// <summary>
  /// All records of the subtree's list, in order and with the Enter flags the merges left (tests):
  /// the count, or -1 when the list path must answer. <paramref name="hits"/> and <paramref name="leaves"/>
  /// must hold <see cref="MaxRecords"/>.
  /// </summary>
  public int IntersectAll(in Vector3d p0, in Vector3d p1, Span<SolidRecord> hits, Span<int> leaves)
  {
    int max = MaxRecords;
    Span<SolidRecord> arena = stackalloc SolidRecord[max];
    Span<byte> leafOf = stackalloc byte[max];
    Span<byte> list = stackalloc byte[max];
    Span<byte> work = stackalloc byte[nodes[0].Work];
    int used = 0;
    int n = Eval(0, p0, p1, arena, leafOf, ref used, list, work);
    for (int k = 0; k < n; k++)
    {
      hits[k] = arena[list[k]];
      leaves[k] = leafOf[list[k]];
    }
    return n;
  }

  /// <summary>Evaluates node <paramref name="ni"/> into <paramref name="dst"/> (arena indices); the count or -1.</summary>
  int Eval(int ni, in Vector3d p0, in Vector3d p1, Span<SolidRecord> arena, Span<byte> leafOf, ref int used,
           Span<byte> dst, Span<byte> work)
  {
    ref Node node = ref nodes[ni];
    if (node.Leaf >= 0)
    {
      int n = Leaves[node.Leaf].RecordSolid!.IntersectAll(p0, p1, arena.Slice(used, node.Max));
      if (n < 0 || n > node.Max)
        return -1;
      for (int k = 0; k < n; k++)
      {
        dst[k] = (byte)(used + k);
        leafOf[used + k] = (byte)node.Leaf;
      }
      used += n;
      return n;
    }

    if (node.ChildCount == 0)
      return 0;   // the list path's null
    int max = node.Max;
    Span<byte> part = work.Slice(0, max);
    Span<byte> merged = work.Slice(max, max);
    Span<byte> rest = work.Slice(2 * max);
    int count = 0;
    bool first = true;
    for (int c = ni + 1; c >= 0; c = nodes[c].Next)
    {
      Vector3d q0 = p0, q1 = p1;
      if (nodes[c].Step >= 0)
        Transform(ref steps[nodes[c].Step], ref q0, ref q1);

      if (first)
      {
        count = Eval(c, q0, q1, arena, leafOf, ref used, dst, rest);
        if (count < 0)
          return -1;
        first = false;
      }
      else
      {
        int n = Eval(c, q0, q1, arena, leafOf, ref used, part, rest);
        if (n < 0)
          return -1;
        if (!(node.Trivial && n == 0))
        {
          count = Merge(node.Table, arena, dst.Slice(0, count), part.Slice(0, n), merged);
          if (count < 0)
            return -1;
          merged.Slice(0, count).CopyTo(dst);
        }
      }
      if (node.ShortCircuit && count == 0)
        break;
    }
    return count;
  }

  /// <summary>One binary step of <see cref="CSGInnerNode"/>: boundaries of (left # right); -1 where that step would not finish.</summary>
  static int Merge(int table, Span<SolidRecord> arena, ReadOnlySpan<byte> left, ReadOnlySpan<byte> right, Span<byte> result)
  {
    int l = 0, r = 0, n = 0;
    bool insideLeft = left.Length > 0 && !arena[left[0]].Enter;
    bool insideRight = right.Length > 0 && !arena[right[0]].Enter;
    bool inside = ((table >> ((insideLeft ? 2 : 0) | (insideRight ? 1 : 0))) & 1) != 0;

    while (l < left.Length || r < right.Length)
    {
      double tl = l < left.Length ? arena[left[l]].T : double.PositiveInfinity;
      double tr = r < right.Length ? arena[right[r]].T : double.PositiveInfinity;
      double t = Math.Min(tl, tr);
      int first = -1;

      // On a tie both advance and the left operand's record represents them. An infinite T against an
      // exhausted operand, or a NaN, would break the list path (a null record, an endless loop): let it answer.
      if (tr == t)
      {
        if (r >= right.Length)
          return -1;
        first = right[r++];
        insideRight = arena[first].Enter;
      }
      if (tl == t)
      {
        if (l >= left.Length)
          return -1;
        first = left[l++];
        insideLeft = arena[first].Enter;
      }
      if (first < 0)
        return -1;

      bool now = ((table >> ((insideLeft ? 2 : 0) | (insideRight ? 1 : 0))) & 1) != 0;
      if (now != inside)
      {
        inside = now;
        arena[first].Enter = now;
        result[n++] = (byte)first;
      }
    }
    return n;
  }

  /// <summary>
  /// <c>p0 = TransformPosition(p0, t)</c>, <c>p1 = TransformVector(p1, t)</c> with the same arithmetic in the
  /// same order (bit-identical), reading the matrix by reference.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal static void Transform(ref Matrix4d t, ref Vector3d p0, ref Vector3d p1)
  {
    double x = p0.X, y = p0.Y, z = p0.Z;
    p0 = new Vector3d(
      x * t.Row0.X + y * t.Row1.X + z * t.Row2.X + t.Row3.X,
      x * t.Row0.Y + y * t.Row1.Y + z * t.Row2.Y + t.Row3.Y,
      x * t.Row0.Z + y * t.Row1.Z + z * t.Row2.Z + t.Row3.Z);
    x = p1.X;
    y = p1.Y;
    z = p1.Z;
    p1 = new Vector3d(
      x * t.Row0.X + y * t.Row1.X + z * t.Row2.X,
      x * t.Row0.Y + y * t.Row1.Y + z * t.Row2.Y,
      x * t.Row0.Z + y * t.Row1.Z + z * t.Row2.Z);
  }
}
