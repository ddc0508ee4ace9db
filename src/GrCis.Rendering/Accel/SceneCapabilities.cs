using System;
using System.Collections.Generic;

namespace Rendering.Accel;

/// <summary>
/// What a prepared scene decided about its members, once, when it was prepared (<see cref="PreparedScene.Prepare"/>):
/// which kernel answers each member, which may live in the BVH, how each solid's hits are completed and whether the
/// library's Phong path shades them. Immutable; read afterwards (the counts of <see cref="PreparedScene"/>, the bench,
/// tests), never derived again per ray or per frame. The decisions themselves are <see cref="LibraryTypes"/>' predicates.
/// </summary>
internal sealed class SceneCapabilities
{
  readonly MemberCapability[] members;

  SceneCapabilities(bool union, MemberCapability[] members, int bounded)
  {
    Union = union;
    this.members = members;
    BoundedCount = bounded;
    foreach (MemberCapability m in members)
    {
      switch (m.Kernel)
      {
        case MemberKernel.Record: RecordKernelCount++; break;
        case MemberKernel.Csg: CsgKernelCount++; break;
        default: ListCount++; break;
      }
      if (m.Kernel == MemberKernel.Csg)
        foreach (MemberCapability leaf in m.Leaves)
          CountShading(leaf);
      else
        CountShading(m);
    }
  }

  void CountShading(in MemberCapability solid)
  {
    if (solid.LibraryPhong)
      LibraryPhongCount++;
    if (solid.Completion != HitCompletion.Full)
      SurfaceCompletionCount++;
  }

  /// <summary>The decisions of <paramref name="members"/> (as the preparation bound them) under union or single-member semantics.</summary>
  internal static SceneCapabilities Of(bool union, PreparedMember[] members)
  {
    var decided = new MemberCapability[members.Length];
    int bounded = 0;
    for (int i = 0; i < members.Length; i++)
    {
      decided[i] = Of(members[i]);
      if (members[i].Bounded)
        bounded++;
    }
    return new SceneCapabilities(union, decided, bounded);
  }

  static MemberCapability Of(in PreparedMember m)
  {
    MemberKernel kernel = m.Csg != null ? MemberKernel.Csg : m.RecordSolid != null ? MemberKernel.Record : MemberKernel.List;
    IReadOnlyList<MemberCapability> leaves = Array.Empty<MemberCapability>();
    if (m.Csg != null)
    {
      var l = new MemberCapability[m.Csg.Leaves.Length];
      for (int k = 0; k < l.Length; k++)
        l[k] = Of(m.Csg.Leaves[k]);
      leaves = l;
    }
    return new MemberCapability(m.Node, kernel, m.Closed, m.Completion, m.LibraryPhong, leaves);
  }

  /// <summary>Union semantics over the members (false: the scene is one member, whose own list answers).</summary>
  public bool Union { get; }

  /// <summary>Every member, in depth-first order of the scene graph.</summary>
  public IReadOnlyList<MemberCapability> Members => members;

  /// <summary>Members answered by their solid's own record kernel.</summary>
  public int RecordKernelCount { get; }

  /// <summary>Non-union CSG subtrees answered by their <see cref="CsgKernel"/>.</summary>
  public int CsgKernelCount { get; }

  /// <summary>Members answered through the LinkedList API.</summary>
  public int ListCount { get; }

  /// <summary>Closed members with a non-empty world box: the BVH's members (of a union).</summary>
  public int BoundedCount { get; }

  /// <summary>Solids (record-kernel members and CSG leaves) whose hits the library's Phong path shades.</summary>
  public int LibraryPhongCount { get; private set; }

  /// <summary>Solids (record-kernel members and CSG leaves) whose hits may be completed surface-only.</summary>
  public int SurfaceCompletionCount { get; private set; }

  /// <summary>The decision for <paramref name="node"/> (a member, or a leaf of a member's CSG kernel), or null when it is neither.</summary>
  public MemberCapability? Of(IIntersectable node)
  {
    foreach (MemberCapability m in members)
    {
      if (ReferenceEquals(m.Node, node))
        return m;
      foreach (MemberCapability leaf in m.Leaves)
        if (ReferenceEquals(leaf.Node, node))
          return leaf;
    }
    return null;
  }
}
