using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>Building a <see cref="PreparedScene"/>: flattening unions, classifying members, bounds.</summary>
public sealed partial class PreparedScene
{
  /// <summary>Prepares <paramref name="root"/> (usually <see cref="IRayScene.Intersectable"/>).</summary>
  public static PreparedScene Prepare(IIntersectable? root)
  {
    var members = new List<PreparedMember>();
    var chain = new List<Matrix4d>();
    var path = new List<Matrix4d>();
    bool union = false;
    if (root != null)
      union = Classify(root, path, members, chain);
    PreparedMember[] prepared = members.ToArray();
    return new PreparedScene(root, union, prepared, chain.ToArray(), SceneCapabilities.Of(union, prepared));
  }

  // ---------------------------------------------------------------- preparation

  static bool IsPureUnion(ISceneNode node) => LibraryTypes.IsFlattenedUnion(node);

  /// <summary>Top level: returns true for union semantics, false for a single member's raw list.</summary>
  static bool Classify(IIntersectable node, List<Matrix4d> path, List<PreparedMember> members, List<Matrix4d> chain)
  {
    if (node is ISceneNode sn && IsPureUnion(sn))
    {
      if (sn.Children.Count == 0)
        return false;
      if (sn.Children.Count == 1)
      {
        // A union of one child returns the child's list unmerged.
        foreach (ISceneNode only in sn.Children)
        {
          int mark = Push(path, only.FromParent);
          bool u = Classify(only, path, members, chain);
          path.RemoveRange(mark, path.Count - mark);
          return u;
        }
      }
      Flatten(sn, path, members, chain);
      return true;
    }
    AddMember(node, path, members, chain);
    return false;
  }

  static void Flatten(ISceneNode node, List<Matrix4d> path, List<PreparedMember> members, List<Matrix4d> chain)
  {
    foreach (ISceneNode child in node.Children)
    {
      int mark = Push(path, child.FromParent);
      if (IsPureUnion(child))
        Flatten(child, path, members, chain);
      else
        AddMember(child, path, members, chain);
      path.RemoveRange(mark, path.Count - mark);
    }
  }

  static int Push(List<Matrix4d> path, in Matrix4d m)
  {
    int mark = path.Count;
    // An identity step is exact to skip (x·1 + y·0 + z·0 + 0 == x for finite coordinates).
    if (m != Matrix4d.Identity)
      path.Add(m);
    return mark;
  }

  static void AddMember(IIntersectable node, List<Matrix4d> path, List<PreparedMember> members, List<Matrix4d> chain)
  {
    var m = new PreparedMember
    {
      Node = node,
      ChainStart = chain.Count,
      ChainCount = path.Count,
      WorldBox = Aabb.Empty,
    };
    chain.AddRange(path);

    if (node is IRecordSolid f && f.RecordsMatchIntersect)
      BindSolid(ref m, f);
    else if (node is ISceneNode csg && CsgKernel.TryCompile(csg) is CsgKernel kernel)
    {
      // A non-union CSG subtree over kernel solids: evaluated without lists (NO_SHADOW if any leaf has it).
      m.Csg = kernel;
      foreach (PreparedMember leaf in kernel.Leaves)
        m.NoShadow |= leaf.NoShadow;
    }

    if (m.RecordSolid != null)
      LibraryTypes.BindShapeCulls(ref m, m.RecordSolid, path);

    if (node is ISceneNode sn && TryClosedBox(sn, out Aabb local))
    {
      // World box from the same chain the ray goes through (padded for rounding).
      Aabb world = local.Transformed(LocalToWorldOf(path));
      if (world.IsEmpty || world.IsFinite)
      {
        m.Closed = true;
        m.WorldBox = world.IsEmpty ? world : world.Padded();
      }
    }
    members.Add(m);
  }

  /// <summary>The member's local-to-world matrix: the inverse of the chain the ray goes through.</summary>
  internal static Matrix4d LocalToWorldOf(List<Matrix4d> path)
  {
    Matrix4d worldToLocal = Matrix4d.Identity;
    for (int k = 0; k < path.Count; k++)
      worldToLocal *= path[k];
    return worldToLocal.Inverted();
  }

  /// <summary>Binds a known solid: its kernel, completion matrices and the attributes resolved once.</summary>
  internal static void BindSolid(ref PreparedMember m, IRecordSolid f)
  {
    m.RecordSolid = f;
    m.Direct = LibraryTypes.DirectKernel(f);
    m.LocalToWorld = f.ToWorld();
    m.WorldToLocal = m.LocalToWorld.Inverted();
    m.LocalToObject = f.ToObject();
    m.NoShadow = f.GetLocalAttribute(PropertyName.NO_SHADOW) != null;

    // The look-ups Intersection.CompleteWith does per hit, once (only when they do not create objects). Without a
    // reflectance model GrCis makes a new PhongModel per hit; it holds no state, so one per member answers the same.
    IReflectanceModel model = f.GetAttribute(PropertyName.REFLECTANCE_MODEL) as IReflectanceModel ?? new PhongModel();
    if (f.GetAttribute(PropertyName.MATERIAL) is IMaterial material)
    {
      m.AttributesCached = true;
      m.Model = model;
      m.Material = material;
      m.Color = f.GetAttribute(PropertyName.COLOR) as double[] ?? material.Color;
      m.Textures = f.GetTextures();
      m.Recursion = f.GetAttribute(PropertyName.RECURSION);
      m.LibraryPhong = m.Recursion == null && LibraryTypes.IsLibraryPhong(model, material);
      m.Completion = CompletionFor(f, m.LibraryPhong, m.Textures);
    }
  }

  /// <summary>World centre and radius of the unit sphere under the chain, when the chain is a similarity (<see cref="EmitterSet.Similarity"/>).</summary>
  internal static bool TrySimilarity(List<Matrix4d> path, out Vector3d center, out double radius)
  {
    Matrix4d l2w = LocalToWorldOf(path);
    center = Vector3d.TransformPosition(Vector3d.Zero, l2w);
    return EmitterSet.Similarity(l2w, out radius) && double.IsFinite(center.X + center.Y + center.Z);
  }

  /// <summary>Local box of a closed member: a closed known solid, or a library CSG node over closed members.</summary>
  static bool TryClosedBox(ISceneNode node, out Aabb box)
  {
    box = Aabb.Empty;
    if (node is IRecordSolid f)
    {
      if (!f.RecordsMatchIntersect || !f.IsClosed)
        return false;
      f.GetBoundingBox(out Vector3d c1, out Vector3d c2);
      box = new Aabb(c1, c2);
      return true;
    }
    if (!LibraryTypes.CombinesChildBoxes(node))
      return false;

    var csg = (CSGInnerNode)node;
    bool first = true;
    foreach (ISceneNode child in csg.Children)
    {
      if (!TryClosedBox(child, out Aabb cb))
        return false;
      cb = cb.Transformed(child.ToParent);
      switch (csg.Operation)
      {
        case SetOperation.Intersection:
          box = first ? cb : Aabb.Intersect(box, cb);
          break;
        case SetOperation.Difference:
          if (first)
            box = cb;
          break;
        default:
          box.Add(cb);
          break;
      }
      first = false;
    }
    if (box.IsEmpty)
      box = Aabb.Empty;
    return true;
  }

  /// <summary>
  /// The surface-only completion a member allows: a library Sphere, Plane, Cube or TriangleMesh (<see cref="LibraryTypes.SurfaceShape"/>),
  /// shaded by the library's Phong model and material with no RECURSION function, and no texture but checkers and image
  /// textures (which read only TextureCoord and the surface colour).
  /// </summary>
  static HitCompletion CompletionFor(IRecordSolid f, bool libraryPhong, LinkedList<ITexture>? textures)
  {
    if (!libraryPhong)
      return HitCompletion.Full;
    bool textured = false;
    if (textures != null)
      foreach (ITexture t in textures)
      {
        if (!LibraryTypes.ReadsOnlyTextureCoord(t))
          return HitCompletion.Full;
        textured = true;
      }
    return LibraryTypes.SurfaceShape(f, textured);
  }
}
