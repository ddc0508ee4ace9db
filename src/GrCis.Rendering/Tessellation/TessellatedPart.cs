using OpenTK.Mathematics;

namespace Rendering.Tessellation;

/// <summary>
/// One solid of the scene graph as triangles in the solid's own (local) space, with the transform that places it in
/// the world as the renderer places it, and the colour it is shaded with.
/// </summary>
public sealed class TessellatedPart
{
  /// <summary>A readable name: the solid's type and its index in the scene, e.g. <c>Sphere 3</c>.</summary>
  public required string Name { get; init; }

  /// <summary>The scene node the triangles come from (a leaf of the scene graph).</summary>
  public required ISceneNode Node { get; init; }

  /// <summary>The name of the node's class, e.g. <c>Sphere</c>, or a script's own class.</summary>
  public string TypeName => Node.GetType().Name;

  /// <summary>Whether the triangles are the surface or only a bounding box (a solid the library does not know).</summary>
  public required PartKind Kind { get; init; }

  /// <summary>
  /// The operation of the nearest CSG node above this leaf that is not a union (the leaf is then one operand of an
  /// intersection, difference or xor, and the surface shown is the operand's, not the result's); null under unions only.
  /// </summary>
  public SetOperation? CsgOperation { get; init; }

  /// <summary>Linear RGB base colour: the node's <see cref="PropertyName.COLOR"/> attribute, else its material's colour (inherited as a hit resolves it).</summary>
  public required Vector3d BaseColor { get; init; }

  /// <summary>Local-to-world matrix (row vectors: a world point is <c>local * LocalToWorld</c>), the product of the <c>ToParent</c> matrices up to the root.</summary>
  public required Matrix4d LocalToWorld { get; init; }

  /// <summary>Vertex positions in the solid's local space.</summary>
  public required Vector3d[] Positions { get; init; }

  /// <summary>Three vertex indices per triangle; <c>Cross(b - a, c - a)</c> points out of a closed solid.</summary>
  public required int[] Indices { get; init; }

  /// <summary>Largest distance (local units) of a point of the triangles from the solid's surface; 0 where the triangles are the surface (cube, mesh, plane).</summary>
  public double Tolerance { get; init; }

  /// <summary>How the part was made, when it is not simply the surface (e.g. an infinite plane cut to a patch).</summary>
  public string? Note { get; init; }

  /// <summary>Number of triangles.</summary>
  public int TriangleCount => Indices.Length / 3;

  /// <summary>Vertex <paramref name="i"/> in world coordinates.</summary>
  public Vector3d WorldPosition(int i) => Vector3d.TransformPosition(Positions[i], LocalToWorld);
}
