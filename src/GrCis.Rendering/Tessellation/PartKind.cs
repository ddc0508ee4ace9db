namespace Rendering.Tessellation;

/// <summary>What the triangles of a <see cref="TessellatedPart"/> stand for.</summary>
public enum PartKind
{
  /// <summary>The solid's own surface (within <see cref="TessellatedPart.Tolerance"/>).</summary>
  Surface,

  /// <summary>
  /// The bounding box of a solid the library cannot tessellate (a script's own class): the box from its
  /// <see cref="ISolid.GetBoundingBox"/>, not its surface.
  /// </summary>
  BoundingBox,
}
