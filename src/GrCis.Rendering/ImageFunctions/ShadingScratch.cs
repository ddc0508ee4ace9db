using System;

namespace Rendering;

/// <summary>
/// Per-thread, per-recursion-depth scratch objects of the shading loop: the material copy that carries
/// the surface colour, and the buffer a secondary ray's colour is returned in. A depth's objects are
/// only used while that depth's shade() runs, so deeper levels never overwrite them.
/// </summary>
internal static class ShadingScratch
{
  [ThreadStatic] static PhongMaterial?[]? materials;
  [ThreadStatic] static double[]?[]? buffers;
  [ThreadStatic] static Intersection?[]? intersections;

  /// <summary>This thread's reusable intersection of <paramref name="depth"/> (the fast path fills it per hit).</summary>
  public static Intersection Intersection(int depth)
  {
    Intersection?[] pool = intersections = Grow(intersections, depth);
    return pool[depth] ??= new Intersection();
  }

  /// <summary>
  /// The material to shade with: <paramref name="m"/> with colour <paramref name="surface"/>. GrCis clones
  /// the material per hit; a plain PhongMaterial is copied into this depth's scratch instead (same values).
  /// </summary>
  public static IMaterial Material(IMaterial m, double[] surface, int depth)
  {
    if (m.GetType() != typeof(PhongMaterial) || depth < 0)
    {
      var clone = (IMaterial)m.Clone();
      clone.Color = surface;
      return clone;
    }
    PhongMaterial?[] pool = materials = Grow(materials, depth);
    PhongMaterial scratch = pool[depth] ??= new PhongMaterial();
    scratch.CopyFrom((PhongMaterial)m, surface);
    return scratch;
  }

  /// <summary>A cleared buffer of <paramref name="bands"/> values owned by <paramref name="depth"/>.</summary>
  public static double[] Buffer(int depth, int bands)
  {
    double[]?[] pool = buffers = Grow(buffers, depth);
    double[]? b = pool[depth];
    if (b == null || b.Length != bands)
      pool[depth] = b = new double[bands];
    else
      Array.Clear(b);
    return b;
  }

  static T?[] Grow<T>(T?[]? pool, int depth) where T : class
  {
    if (pool != null && depth < pool.Length)
      return pool;
    var bigger = new T?[Math.Max(depth + 1, 16)];
    pool?.CopyTo(bigger, 0);
    return bigger;
  }
}
