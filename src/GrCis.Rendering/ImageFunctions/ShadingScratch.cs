using System;

namespace Rendering;

/// <summary>
/// One worker's shading state (part of its <see cref="Execution.WorkerContext"/>), fetched once per shaded ray
/// instead of once per use: its ray and hit counts, the observer of its render (<see cref="Execution.RenderContext"/>), and per recursion depth the reusable intersection, the material copy that
/// carries the surface colour and the buffer a secondary ray's colour is returned in. A depth's objects are
/// only used while that depth's shade() runs, so deeper levels never overwrite them.
/// </summary>
internal sealed class ShadingScratch
{
  /// <summary>The calling thread's scratch (its <see cref="Execution.WorkerContext"/>'s).</summary>
  public static ShadingScratch Current
  {
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    get => Execution.WorkerContext.Current.Get(slot);
  }

  static readonly Execution.WorkerSlot<ShadingScratch> slot = new(() => new ShadingScratch());

  /// <summary>The shading scratch of <paramref name="worker"/>.</summary>
  public static ShadingScratch Of(Execution.WorkerContext worker) => worker.Get(slot);

  /// <summary>Makes <paramref name="scratch"/> the shading scratch of <paramref name="worker"/>.</summary>
  public static void Set(Execution.WorkerContext worker, ShadingScratch scratch) => worker.Set(slot, scratch);

  /// <summary>Shades for <paramref name="render"/>: its observer, noise estimate and prepared scenes.</summary>
  public void UseRender(Execution.RenderContext render)
  {
    Observer = render.Observer;
    Noise = render.Noise;
    Queries = render.Queries;
    LastPrepared = null;
  }

  /// <summary>Rays counted on this thread (<see cref="Execution.RayCounter"/>).</summary>
  public long Rays;

  /// <summary>Of those, rays that hit something (blocked shadow rays included).</summary>
  public long Hits;

  /// <summary>The observer of the render this thread works for (<see cref="Execution.RenderContext"/>); null = none.</summary>
  public Observation.RayObserver? Observer;

  /// <summary>Where the render this thread works for keeps its noise estimate (<see cref="Execution.RenderContext.Noise"/>); null = none.</summary>
  public Execution.NoiseImage? Noise;

  /// <summary>The prepared scenes of the render this thread works for (<see cref="Execution.RenderContext.Queries"/>), else the thread's own.</summary>
  public Accel.SceneQueries Queries
  {
    get => queries ??= own ??= new Accel.SceneQueries();
    set => queries = value;
  }

  Accel.SceneQueries? queries, own;

  /// <summary>The snapshot this thread used last (checked first: the scene rarely changes between rays).</summary>
  public Accel.PreparedScene? LastPrepared;

  /// <summary>The scene as the Whitted kernel of this frame read it for this thread (<see cref="Accel.BoundScene"/>).</summary>
  public Accel.BoundScene? Bound;

  /// <summary>True while a faithful (GrCis-style, no search structure) query runs on this thread (<see cref="Accel.ExhaustiveSearch"/>).</summary>
  public bool ExhaustiveSearch;

  /// <summary>Kind of the next shaded ray, set by its caller for the observer; read once, then back to Secondary.</summary>
  public Observation.RayKind NextKind = Observation.RayKind.Secondary;

  /// <summary>
  /// Tells the observer, if any, that a ray of recursion <paramref name="depth"/> begins; returns its kind (depth 0 is
  /// the camera's ray, a deeper one was classified by the code that spawned it with <see cref="NextRay"/>).
  /// </summary>
  public Observation.RayKind BeginRay(int depth, in OpenTK.Mathematics.Vector3d origin, in OpenTK.Mathematics.Vector3d direction)
  {
    if (Observer == null)
      return Observation.RayKind.Primary;
    Observation.RayKind kind = depth == 0 ? Observation.RayKind.Primary : NextKind;
    NextKind = Observation.RayKind.Secondary;
    Observer.BeginRay(kind, depth, origin, direction);
    return kind;
  }

  /// <summary>Tells the observer, if any, that the ray begun by <see cref="BeginRay"/> ended at <paramref name="hit"/> (null: it left the scene).</summary>
  public void EndRay(Observation.RayKind kind, int depth, in OpenTK.Mathematics.Vector3d origin, in OpenTK.Mathematics.Vector3d direction, Intersection? hit) =>
    Observer?.EndRay(kind, depth, origin, direction, hit);

  /// <summary>The kind of the next ray to be shaded (reflected, refracted), for the observer.</summary>
  public void NextRay(Observation.RayKind kind)
  {
    if (Observer != null)
      NextKind = kind;
  }

  PhongMaterial?[] materials = new PhongMaterial?[16];
  double[]?[] buffers = new double[]?[16];
  Intersection?[] intersections = new Intersection?[16];

  /// <summary>This thread's reusable intersection of <paramref name="depth"/> (the fast path fills it per hit).</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]   // once per ray
  public Intersection Intersection(int depth)
  {
    Intersection?[] pool = intersections;
    if (depth >= pool.Length)
      intersections = pool = Grow(pool, depth);
    return pool[depth] ??= new Intersection();
  }

  /// <summary>
  /// The material to shade with: <paramref name="m"/> with colour <paramref name="surface"/>. GrCis clones
  /// the material per hit; a plain PhongMaterial is copied into this depth's scratch instead (same values).
  /// </summary>
  public IMaterial Material(IMaterial m, double[] surface, int depth)
  {
    if (!Accel.LibraryTypes.CopiesIntoScratch(m) || depth < 0)
    {
      var clone = (IMaterial)m.Clone();
      clone.Color = surface;
      return clone;
    }
    PhongMaterial?[] pool = materials;
    if (depth >= pool.Length)
      materials = pool = Grow(pool, depth);
    PhongMaterial scratch = pool[depth] ??= new PhongMaterial();
    scratch.CopyFrom((PhongMaterial)m, surface);
    return scratch;
  }

  /// <summary>A cleared buffer of <paramref name="bands"/> values owned by <paramref name="depth"/>.</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]   // once per ray
  public double[] Buffer(int depth, int bands)
  {
    double[]?[] pool = buffers;
    if (depth >= pool.Length)
      buffers = pool = Grow(pool, depth);
    double[]? b = pool[depth];
    if (b == null || b.Length != bands)
      pool[depth] = b = new double[bands];
    else
      Accel.WhittedKernel.Zero(b);
    return b;
  }

  // Called only to grow: storing a pool field on every call cost a GC write barrier per ray.
  static T?[] Grow<T>(T?[] pool, int depth) where T : class
  {
    var bigger = new T?[Math.Max(depth + 1, 2 * pool.Length)];
    pool.CopyTo(bigger, 0);
    return bigger;
  }
}
