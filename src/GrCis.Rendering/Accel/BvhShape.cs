namespace Rendering.Accel;

/// <summary>
/// How a <see cref="Bvh"/> trades depth for leaf size. A node of at most <see cref="SmallLeaf"/> items is
/// a leaf; one of more than <see cref="LargeLeaf"/> is always split; in between the surface-area
/// heuristic decides, an item test costing <see cref="ItemCost"/> node visits.
/// </summary>
internal readonly record struct BvhShape(int SmallLeaf, int LargeLeaf, double ItemCost)
{
  /// <summary>Scene members: an item test runs a transform chain and a solid, so leaves stay small.</summary>
  public static readonly BvhShape SceneMembers = new(1, 4, 2.0);

  /// <summary>Triangles: a test is one Möller–Trumbore, so leaves of up to 16 are allowed where SAH prefers them.</summary>
  public static readonly BvhShape Triangles = new(4, 16, 1.0);
}
