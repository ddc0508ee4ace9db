using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Observation;

namespace Rendering;

/// <summary>Ray casting: the first hit lit by every light, without shadows or secondary rays.</summary>
[Serializable]
public class RayCasting : IImageFunction
{
  /// <summary>Factor of the path hash for each light that lit the hit.</summary>
  protected internal const long HASH_LIGHT = 101L;

  /// <summary>Factor of the path hash for each texture applied to the hit (with the texture's own hash).</summary>
  protected internal const long HASH_TEXTURE = 11L;

  /// <summary>The scene given to the constructor or set through <see cref="Scene"/>; null = the scene being rendered (<see cref="MT.scene"/>).</summary>
  protected IRayScene? scene;

  /// <summary>How ray queries are answered: the prepared fast path (default) or the faithful GrCis path.</summary>
  public AccelMode Accel = AccelMode.Bvh;



  // The snapshot of the last Prepare or first use, for statistics and tests (not a cache: the render context keeps those).
  [NonSerialized] PreparedScene? lastPrepared;

  /// <summary>
  /// On the fast path, fill one <see cref="Intersection"/> per thread and recursion depth instead of a new
  /// one per hit (default). Such an intersection is valid until the next hit at its depth; a component that
  /// keeps intersections (a texture or recursion function in a script) may set this to false.
  /// Ignored when a subclass overrides <see cref="FirstHit(Vector3d, Vector3d)"/>.
  /// </summary>
  public bool ReuseIntersections = true;

  [NonSerialized] internal readonly bool firstHitOverridden;

  /// <summary>A ray caster of scene <paramref name="sc"/> (null: the scene being rendered, <see cref="MT.scene"/>).</summary>
  public RayCasting(IRayScene? sc = null)
  {
    scene = sc;
    firstHitOverridden = LibraryTypes.OverridesFirstHit(GetType());
  }

  /// <summary>
  /// Copies every setting (public field) of <paramref name="source"/> into this object, not its scene
  /// or caches: how a per-frame or instrumented copy of a script's image function keeps the script's choices.
  /// Subclasses with settings of their own extend it.
  /// </summary>
  public virtual void CopySettingsFrom(RayCasting source)
  {
    ArgumentNullException.ThrowIfNull(source);
    Accel = source.Accel;
    ReuseIntersections = source.ReuseIntersections;
  }

  /// <summary>
  /// First hit of a ray traced at recursion <paramref name="depth"/>: <see cref="FirstHit(Vector3d, Vector3d)"/>,
  /// or on the fast path the same hit in this thread's reusable intersection of that depth.
  /// </summary>
  protected Intersection? FirstHitAt(int depth, Vector3d p0, Vector3d p1) => FirstHitAt(ShadingScratch.Current, depth, p0, p1);

  /// <summary><see cref="FirstHitAt(int, Vector3d, Vector3d)"/> with the thread's scratch already at hand.</summary>
  internal Intersection? FirstHitAt(ShadingScratch scratch, int depth, Vector3d p0, Vector3d p1)
  {
    if (firstHitOverridden || !ReuseIntersections || depth < 0)
      return FirstHit(p0, p1);
    PreparedScene? ps = PreparedFor(scratch);
    if (ps == null)
      return FirstHit(p0, p1);
    scratch.Rays++;
    return ps.FirstHit(p0, p1, scratch.Intersection(depth), ReferenceEquals(ps, surfaceOnly));
  }

  // What this function reads from the hits of the snapshot made by Prepare, decided there once: HitData.Surface
  // when only this library's shading reads them (LibraryShadingOnly, for that scene's lights), else everything.
  // A snapshot built on first use, for another scene, gets HitData.All.
  [NonSerialized] internal PreparedScene? surfaceOnly;

  /// <summary>
  /// What this image function reads from the hits it shades (<see cref="HitData"/>): <see cref="HitData.Surface"/>
  /// for the library's own shading, including a subclass that overrides none of the methods that see hits
  /// (<see cref="HitReaders"/>); <see cref="HitData.All"/> for one that does. A subclass that overrides them
  /// but reads only the surface may say so here and keep the cheaper hits.
  /// </summary>
  protected virtual HitData HitDataRead => LibraryTypes.ReadsWholeHits(GetType()) ? HitData.All : HitData.Surface;

  /// <summary>The virtual methods of RayCasting and RayTracing that see a hit: a subclass overriding one may read anything.</summary>
  public static readonly System.Collections.Generic.IReadOnlyList<string> HitReaders =
    new[] { nameof(GetSample), FirstHitName, RayTracing.ShadeName, RayTracing.OccludedName, RayTracing.ShadowTransmittanceName };

  internal const string FirstHitName = nameof(FirstHit);

  /// <summary>
  /// True when nothing but the library's own code reads a shaded hit, decided once per prepared scene: the
  /// function reads only <see cref="HitData.Surface"/>, no ray registerer receives hits, and every light is a
  /// library light (they read only the world point and normal). Materials, reflectance models and textures are
  /// checked per member (<see cref="HitCompletion"/>).
  /// </summary>
  bool LibraryShadingOnly(IRayScene sc)
  {
    if ((HitDataRead & HitData.LocalFrame) != 0 || this is RayTracing { rayRegisterer: not null })
      return false;
    if (sc.Sources != null)
      foreach (ILightSource light in sc.Sources)
        if (!LibraryTypes.IsLibraryLight(light))
          return false;
    return true;
  }

  /// <summary>
  /// Prepares <paramref name="sc"/> (default: <see cref="Scene"/>) for the fast path: call once per frame,
  /// after the scene graph is final (the tile renderer does). Returns null in <see cref="AccelMode.None"/>.
  /// </summary>
  public PreparedScene? Prepare(IRayScene? sc = null)
  {
    if (Accel == AccelMode.None)
      return null;
    IIntersectable? source = (sc ?? Scene).Intersectable;
    if (source == null)
      return null;
    ShadingScratch scratch = ShadingScratch.Current;
    PreparedScene ps = scratch.Queries.Prepare(source);
    surfaceOnly = LibraryShadingOnly(sc ?? Scene) ? ps : null;
    scratch.LastPrepared = lastPrepared = ps;
    return ps;
  }

  /// <summary>The snapshot made by the last <see cref="Prepare"/> or first use (statistics, tests).</summary>
  public PreparedScene? LastPrepared => lastPrepared;

  /// <summary>The prepared snapshot of the current scene (built on first use), or null on the faithful path.</summary>
  protected PreparedScene? Prepared => PreparedFor(ShadingScratch.Current);

  /// <summary>
  /// The prepared snapshot of the current scene from the queries of the render this thread works for (or the
  /// thread's own outside a render); the thread's last snapshot is checked first, so a ray costs one comparison.
  /// </summary>
  internal PreparedScene? PreparedFor(ShadingScratch scratch)
  {
    if (Accel == AccelMode.None)
      return null;
    IIntersectable? source = Scene.Intersectable;
    PreparedScene? ps = scratch.LastPrepared;
    if (ps != null && ps.Source == source)
      return ps;
    if (source == null)
      return null;
    scratch.LastPrepared = lastPrepared = ps = scratch.Queries.For(source);
    return ps;
  }

  /// <summary>The scene this function is bound to (given to the constructor or set), or null: it renders <see cref="MT.scene"/>.</summary>
  public IRayScene? BoundScene => scene;

  /// <summary>The scene: the one given to the constructor, else the thread's current scene.</summary>
  public IRayScene Scene
  {
    get => scene ?? MT.scene ?? throw new InvalidOperationException("The image function has no scene to render.");
    set => scene = value;
  }

  /// <summary>Width of the image in pixels: the camera's (setting it sets the camera's).</summary>
  public virtual double Width
  {
    get => Scene.Camera?.Width ?? 0.0;
    set { if (Scene.Camera != null) Scene.Camera.Width = value; }
  }

  /// <summary>Height of the image in pixels: the camera's (setting it sets the camera's).</summary>
  public virtual double Height
  {
    get => Scene.Camera?.Height ?? 0.0;
    set { if (Scene.Camera != null) Scene.Camera.Height = value; }
  }

  /// <summary>
  /// The query of the scene being shaded (<see cref="ISceneQuery"/>: first hit, shadow any-hit): the prepared
  /// scene, or GrCis's own lists with <see cref="AccelMode.None"/>. Same hits either way.
  /// </summary>
  protected ISceneQuery Query => (ISceneQuery?)Prepared ?? Lists;

  [NonSerialized] SceneLists? lists;

  /// <summary>GrCis's list search of the current scene (kept while the scene's root stays the same).</summary>
  internal SceneLists Lists
  {
    get
    {
      IIntersectable? source = Scene.Intersectable;
      SceneLists? l = lists;
      if (l == null || l.Source != source)
        lists = l = new SceneLists(source);
      return l;
    }
  }

  /// <summary>First hit of the ray (fully completed), or null; a subclass may override it (then every ray comes here).</summary>
  protected virtual Intersection? FirstHit(Vector3d p0, Vector3d p1)
  {
    RayCounter.CountRay();
    return Query.FirstHit(p0, p1);
  }

  /// <summary>
  /// All records along the ray from the whole scene (the LinkedList API), searched as the current
  /// <see cref="Accel"/> mode says: with <see cref="AccelMode.None"/> without any search structure.
  /// </summary>
  protected LinkedList<Intersection>? IntersectScene(Vector3d p0, Vector3d p1) =>
    Accel == AccelMode.None ? Lists.AllHits(p0, p1) : Scene.Intersectable?.Intersect(p0, p1);

  /// <summary>Completes the hit and applies its textures; returns the hash of the solid and texture cells.</summary>
  protected internal static long CompleteAndTexture(Intersection i)
  {
    i.Complete();
    long hash = i.Solid?.GetHashCode() ?? 0L;
    if (i.Textures != null)
      foreach (ITexture tex in i.Textures)
        hash = hash * HASH_TEXTURE + tex.Apply(i);
    return hash;
  }

  /// <summary>
  /// The colour of image point (<paramref name="x"/>, <paramref name="y"/>) (in pixels, from the top left corner): the
  /// camera's ray through it, its first hit lit directly by every light (no shadows, no secondary rays), or the
  /// background colour. Returns the hash of the solid, textures and lights (1 when the camera gives no ray).
  /// </summary>
  public virtual long GetSample(double x, double y, double[] color)
  {
    MT.doubleX = x;
    MT.doubleY = y;
    IRayScene sc = Scene;
    Array.Clear(color);
    if (sc.Camera == null || !sc.Camera.GetRay(x, y, out Vector3d p0, out Vector3d p1))
      return 1L;

    ShadingScratch scratch = ShadingScratch.Current;
    Intersection? i = FirstHitAt(scratch, 0, p0, p1);
    if (scratch.Observer is RayObserver observer)
    {
      // Ray casting traces one ray per sample: reported once its hit is complete.
      long h = Cast(sc, i, p1, color);
      observer.BeginRay(RayKind.Primary, 0, p0, p1);
      observer.EndRay(RayKind.Primary, 0, p0, p1, i);
      return h;
    }
    return Cast(sc, i, p1, color);
  }

  long Cast(IRayScene sc, Intersection? i, Vector3d p1, double[] color)
  {
    if (i == null)
    {
      if (sc.BackgroundColor != null)
        Array.Copy(sc.BackgroundColor, color, Math.Min(color.Length, sc.BackgroundColor.Length));
      return 0L;
    }
    ShadingScratch.Current.Hits++;

    long hash = CompleteAndTexture(i);
    double[] surface = i.SurfaceColor!;
    if (sc.Sources == null || sc.Sources.Count == 0)
    {
      Array.Copy(surface, color, Math.Min(color.Length, surface.Length));
      return hash;
    }

    Vector3d viewer = -p1.Normalized();
    i.Material = ShadingScratch.Current.Material(i.Material!, surface, 0);

    foreach (ILightSource source in sc.Sources)
    {
      double[]? intensity = source.GetIntensity(i, out Vector3d dir);
      if (intensity == null)
        continue;
      double[]? reflection = i.ReflectanceModel!.ColorReflection(i, dir, viewer, ReflectionComponent.ALL);
      if (reflection == null)
        continue;
      for (int b = 0; b < color.Length; b++)
        color[b] += intensity[Math.Min(b, intensity.Length - 1)] * reflection[Math.Min(b, reflection.Length - 1)];
      hash = hash * HASH_LIGHT + source.GetHashCode();
    }
    return hash;
  }
}
