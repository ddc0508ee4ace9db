namespace Rendering.Accel;

/// <summary>How ray queries are answered.</summary>
public enum AccelMode
{
  /// <summary>
  /// Faithful GrCis path: every query goes through <see cref="IIntersectable.Intersect"/> of the whole scene,
  /// with no search structure anywhere (a <see cref="TriangleMesh"/> tests every triangle, as in GrCis), and
  /// <see cref="RayTracing"/> samples through its own <see cref="RayTracing.shade"/> (no prepared kernel).
  /// </summary>
  None = 0,

  /// <summary>Prepared scene: flattened unions, cached matrices, a BVH and allocation-free kernels (the default).</summary>
  Bvh = 1,
}
