using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// One leaf of a flattened scene: a known solid answered by its <see cref="IRecordSolid"/> kernel, or any
/// non-union CSG subtree over such solids (<see cref="Csg"/>), or any other intersectable (CSG over meshes,
/// script solids) answered through its LinkedList API.
/// </summary>
internal struct PreparedMember
{
  public IIntersectable Node;

  /// <summary>Non-null when the allocation-free kernel answers for this member.</summary>
  public IRecordSolid? RecordSolid;

  /// <summary>The library solid <see cref="RecordSolid"/> is, when the kernels call it directly.</summary>
  public DirectSolid Direct;

  /// <summary>Non-null for a non-union CSG subtree evaluated by its allocation-free kernel (then <see cref="RecordSolid"/> is null).</summary>
  public CsgKernel? Csg;

  /// <summary>FromParent matrices from the scene root down to this member (identities left out), in order.</summary>
  public int ChainStart, ChainCount;

  /// <summary>Records only inside <see cref="WorldBox"/> and balanced: may live in the BVH.</summary>
  public bool Closed;

  /// <summary>
  /// A conservative world bounding sphere (radius² &gt; 0) of a closed member whose records all lie on a
  /// sphere under a similarity transform: a cheap test that skips the transform chain on a clear miss.
  /// </summary>
  public Vector3d CullCenter;
  public double CullRadius2;

  /// <summary>
  /// For a bounded plane (an open member): a padded world box around the rectangle or triangle. Its one record,
  /// at any t, lies in it, so a line that misses the box has no record and the member is skipped without its
  /// transform chain (exact: conservative).
  /// </summary>
  public Aabb LineBox;
  public bool HasLineBox;

  /// <summary>
  /// For a plane member: its local z as an affine function of the world point (x, y, z, offset), and the same over the
  /// chain's absolute values (<see cref="PlaneCull"/>); valid when <see cref="HasPlaneZ"/>.
  /// </summary>
  public Vector4d PlaneZ, PlaneZAbs;
  public bool HasPlaneZ;

  /// <summary>The solid's local NO_SHADOW attribute was set at prepare time.</summary>
  public bool NoShadow;

  public Aabb WorldBox;

  /// <summary>Closed with a non-empty world box: a member of the scene's BVH (a closed member with an empty box has no
  /// records and is left out of every query; an open one is tested for every ray).</summary>
  public readonly bool Bounded => Closed && !WorldBox.IsEmpty;

  /// <summary>Attributes resolved at prepare time (reflectance model and material found; else per hit).</summary>
  public bool AttributesCached;
  public IReflectanceModel? Model;
  public IMaterial? Material;
  public double[]? Color;
  public System.Collections.Generic.LinkedList<ITexture>? Textures;
  public object? Recursion;

  /// <summary>Shaded by the library's Phong model and material, no recursion function (<see cref="LibraryTypes.IsLibraryPhong"/>).</summary>
  public bool LibraryPhong;

  /// <summary>What a surface-only completion may leave out for this member (when the caller allows it).</summary>
  public HitCompletion Completion;

  // What Intersection.Complete() would compute (Solid.ToWorld(), its inverse, Solid.ToObject()).
  public Matrix4d LocalToWorld, WorldToLocal, LocalToObject;
}
