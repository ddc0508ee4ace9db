namespace Rendering.Accel;

/// <summary>
/// How a <see cref="Bvh"/> trades depth for leaf size. A node of at most <see cref="SmallLeaf"/> items is
/// a leaf; one of more than <see cref="LargeLeaf"/> is always split; in between the surface-area
/// heuristic decides. A leaf's items are tested <see cref="Block"/> at a time (a partly filled block costs a whole
/// one; a power of two), a block test costing <see cref="BlockCost"/> node visits; the SAH counts every side of a
/// split in blocks too.
/// <see cref="Bins"/> bin planes per axis (at most <see cref="BvhBuilder.MaxBins"/>).
/// </summary>
internal readonly record struct BvhShape(int SmallLeaf, int LargeLeaf, double BlockCost, int Block = 1, int Bins = 16)
{
  /// <summary>Scene members: an item test runs a transform chain and a solid, so leaves stay small.</summary>
  public static readonly BvhShape SceneMembers = new(1, 4, 2.0);

  /// <summary>
  /// Triangles: the mesh walk tests them four at a time (<see cref="TriangleBlock"/>), so a leaf of 1 to 4 costs one
  /// block test and one of 5 costs two; leaves of up to 16 (four blocks) where SAH prefers them. A block test (four
  /// triangles in doubles) costs three binary node steps: 2 to 3 alike on the Buddha, 3 best on other meshes, 1 (Embree's
  /// ratio) and per-triangle costs slower. 32 bins: a few per cent faster walks for about 5 % more build time.
  /// </summary>
  public static readonly BvhShape Triangles = new(4, 16, 3.0, Block: 4, Bins: 32);

  /// <summary>Blocks a leaf of <paramref name="items"/> items takes.</summary>
  public int Blocks(int items) => (items + Block - 1) / Block;
}
