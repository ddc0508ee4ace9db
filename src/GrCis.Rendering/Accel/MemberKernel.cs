namespace Rendering.Accel;

/// <summary>What answers the rays of one prepared member.</summary>
internal enum MemberKernel : byte
{
  /// <summary>The solid's own allocation-free record kernel (<see cref="IRecordSolid.IntersectFirst"/>).</summary>
  Record,

  /// <summary>A non-union CSG subtree evaluated by its <see cref="CsgKernel"/>.</summary>
  Csg,

  /// <summary>GrCis's LinkedList API (<see cref="IIntersectable.Intersect"/>): a script's solid, a mesh in CSG, a subclass that merges its own way.</summary>
  List,
}
