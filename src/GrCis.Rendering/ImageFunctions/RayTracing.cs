using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using MathSupport;
using OpenTK.Mathematics;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Observation;

namespace Rendering;

/// <summary>
/// Whitted ray tracing: local Phong lighting with shadow rays, then mirrored and refracted rays
/// recursively while their importance stays above <see cref="MinImportance"/> and the depth below
/// <see cref="MaxLevel"/>. Solids with a <see cref="PropertyName.RECURSION"/> attribute shade themselves.
/// </summary>
[Serializable]
public partial class RayTracing : RayCasting
{
  protected const long HASH_REFRACT = 13L;
  protected const long HASH_REFLECT = 17L;
  protected const long HASH_RECURSION = 101L;

  /// <summary>Maximal depth of secondary rays.</summary>
  public int MaxLevel = 12;

  /// <summary>Secondary rays weaker than this are not traced.</summary>
  public double MinImportance = 0.05;

  public bool DoShadows = true;
  public bool DoReflections = true;
  public bool DoRefractions = true;

  /// <summary>Honour solids' <see cref="RecursionFunction"/> attributes.</summary>
  public bool DoRecursion = true;

  /// <summary>
  /// Opt-in (GrCis: off): transparent occluders let light through, scaled by their Kt at every
  /// surface the shadow ray enters, instead of blocking it.
  /// </summary>
  public bool TransparentShadows;

  /// <summary>
  /// Opt-in (GrCis: off): the refracted ray is weighted by Kt·(1 − F) with F Schlick's Fresnel
  /// reflectance of the interface, instead of the raw Kt.
  /// </summary>
  public bool FresnelRefraction;

  public RayTracing(IRayScene? sc = null) : base(sc) =>
    occludedOverridden = LibraryTypes.OverridesOccluded(GetType());

  /// <inheritdoc/>
  public override void CopySettingsFrom(RayCasting source)
  {
    base.CopySettingsFrom(source);
    if (source is not RayTracing rt)
      return;
    MaxLevel = rt.MaxLevel;
    MinImportance = rt.MinImportance;
    DoShadows = rt.DoShadows;
    DoReflections = rt.DoReflections;
    DoRefractions = rt.DoRefractions;
    DoRecursion = rt.DoRecursion;
    TransparentShadows = rt.TransparentShadows;
    FresnelRefraction = rt.FresnelRefraction;
    rayRegisterer = rt.rayRegisterer;
  }

  // A subclass's Occluded must see every shadow ray; otherwise the scratch at hand counts it.
  [NonSerialized] readonly bool occludedOverridden;

  public override long GetSample(double x, double y, double[] color) => Sample(x, y, color);

  /// <summary>
  /// <see cref="GetSample"/> of this class itself, which the sample loop calls directly for a function of exactly
  /// this type. The library's own scene and camera are read without interface calls, which code compiled without a
  /// profile (ReadyToRun, a render's first moments) would otherwise pay per sample (docs/performance.md, "A render's first moments").
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal long Sample(double x, double y, double[] color)
  {
    WorkerContext context = WorkerContext.Current;
    context.DoubleX = x;
    context.DoubleY = y;
    Zero(color);
    IRayScene sc = Scene;
    ICamera? camera = LibraryScene.Is(sc) ? Unsafe.As<DefaultRayScene>(sc).Camera : sc.Camera;
    if (camera == null)
      return 11L;
    Vector3d p0, p1;
    if (camera.GetType() == typeof(StaticCamera))
      Unsafe.As<StaticCamera>(camera).Ray(x, y, out p0, out p1);
    else if (!camera.GetRay(x, y, out p0, out p1))
      return 11L;
    return shade(0, 1.0, ref p0, ref p1, color);
  }

  /// <summary>True when something (not marked NO_SHADOW) lies between the point and the light at <c>p0 + dir</c>.</summary>
  // Names of the hit-reading virtuals for RayCasting.HitReaders: constants, so no static initialization order matters.
  internal const string ShadeName = nameof(shade), OccludedName = nameof(Occluded), ShadowTransmittanceName = nameof(ShadowTransmittance);

  protected virtual bool Occluded(Vector3d p0, Vector3d dir) => Occluded(ShadingScratch.Current, p0, dir);

  /// <summary>
  /// The shadow query every shading path asks: a subclass's own <see cref="Occluded(Vector3d, Vector3d)"/> when it
  /// overrides it, else the scratch at hand answers (and counts the ray).
  /// </summary>
  private protected bool Blocked(ShadingScratch scratch, Vector3d p0, Vector3d dir) =>
    occludedOverridden ? Occluded(p0, dir) : Occluded(scratch, p0, dir);

  bool Occluded(ShadingScratch scratch, Vector3d p0, Vector3d dir)
  {
    scratch.Rays++;
    PreparedScene? ps = PreparedFor(scratch);
    return ps != null ? ps.AnyHit(p0, dir) : Lists.AnyHit(p0, dir);
  }

  /// <summary>Receives every ray traced, when set (GrCis's 048 ray visualiser API); null costs nothing.</summary>
  [NonSerialized]
  public AbstractRayRegisterer? rayRegisterer;

  /// <summary>
  /// Colour seen along the ray <c>p0 + t p1</c>, written to <paramref name="color"/>; returns the path hash.
  /// The ray is reported to the render's observer, when one is attached (<see cref="RenderContext.Observer"/>).
  /// </summary>
  [System.Runtime.CompilerServices.SkipLocalsInit]   // the stack buffers are written before they are read
  public virtual long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    ShadingScratch scratch = ShadingScratch.Current;
    RayObserver? observer = scratch.Observer;
    int rayDepth = depth;
    RayKind kind = RayKind.Primary;
    if (observer != null)
    {
      // Depth 0 is the camera's ray; deeper rays were classified by the code that spawned them.
      kind = depth == 0 ? RayKind.Primary : scratch.NextKind;
      scratch.NextKind = RayKind.Secondary;
      observer.BeginRay(kind, depth, p0, p1);
    }

    IRayScene sc = Scene;
    Vector3d direction = p1;
    Intersection? i = FirstHitAt(scratch, depth, p0, direction);
    long hash;
    bool library = LibraryScene.Is(sc);
    if (i == null)
    {
      rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerNormal, depth, p0, direction * 100000.0);
      IBackground? background = library ? Unsafe.As<DefaultRayScene>(sc).Background : sc.Background;
      if (background != null)
        hash = background.GetType() == typeof(DefaultBackground)
          ? Unsafe.As<DefaultBackground>(background).Fill(color)
          : background.GetColor(p1, color);
      else
      {
        FillBackground(sc, color);
        hash = 1L;
      }
      goto done;
    }

    scratch.Hits++;   // counted here, on a branch taken anyway
    hash = CompleteAndTexture(i);
    rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.unknown, depth, p0, i);
    int bands = color.Length;
    Zero(color);

    if (DoRecursion && i.RecursionAttribute is RecursionFunction recursion)
    {
      hash = ShadeRecursion(recursion, i, depth, importance, ref direction, color, hash);
      goto done;
    }

    Vector3d viewer = -p1.Normalized();
    double[] surface = i.SurfaceColor!;

    ICollection<ILightSource>? sources = library ? Unsafe.As<DefaultRayScene>(sc).Sources : sc.Sources;
    if (sources == null || sources.Count == 0)
      AddScaled(color, surface, 1.0);
    else
    {
      i.Material = scratch.Material(i.Material!, surface, depth);
      // The library's Phong model writes into a stack buffer instead of a new array per light.
      bool phong = LibraryTypes.IsLibraryPhongModel(i.ReflectanceModel) && i.Material is PhongMaterial && surface.Length <= 16;
      Span<double> buffer = stackalloc double[16];

      // A LinkedList (GrCis's type) is walked by nodes: no boxed enumerator per hit.
      if (sources is LinkedList<ILightSource> linked)
      {
        for (LinkedListNode<ILightSource>? n = linked.First; n != null; n = n.Next)
          hash = AddLight(scratch, n.Value, i, viewer, phong, surface, buffer, color, hash);
      }
      else
        foreach (ILightSource source in sources)
          hash = AddLight(scratch, source, i, viewer, phong, surface, buffer, color, hash);
    }

    if (depth++ >= MaxLevel || (!DoReflections && !DoRefractions))
      goto done;

    double[] comp = scratch.Buffer(depth, bands);
    Vector3d origin = i.CoordWorld;
    Vector3d viewerUnit = default;
    bool haveUnit = false;

    if (DoReflections)
    {
      Vector3d r = Geometry.SpecularReflection(i.Normal, viewer);
      Span<double> ksBuffer = stackalloc double[16];
      scoped ReadOnlySpan<double> ks = default;
      bool have;
      if (LibraryTypes.IsLibraryPhongModel(i.ReflectanceModel) && i.Material is PhongMaterial pm && pm.Color.Length is > 0 and <= 16)
      {
        Span<double> k = ksBuffer[..pm.Color.Length];
        if (viewer.X == 0.0 && viewer.Y == 0.0 && viewer.Z == 0.0)
          PhongModel.ColorReflection(pm, i.Normal, viewer, r, ReflectionComponent.SPECULAR_REFLECTION, k);
        else
        {
          // The model's normalized input, kept for the refracted direction (which normalizes the same vector).
          viewerUnit = viewer.Normalized();
          haveUnit = true;
          PhongModel.Directional(pm, i.Normal, viewerUnit, r, ReflectionComponent.SPECULAR_REFLECTION, k);
        }
        ks = k;
        have = true;
      }
      else
      {
        double[]? arr = i.ReflectanceModel!.ColorReflection(i, viewer, r, ReflectionComponent.SPECULAR_REFLECTION);
        have = arr != null;
        if (have)
          ks = arr;
      }
      if (have)
      {
        double newImportance = importance * MaxBand(ks);
        if (newImportance >= MinImportance)
        {
          if (ReflectionDirection(i, r, depth, out Vector3d reflected))
          {
            if (observer != null)
              scratch.NextKind = RayKind.Reflected;
            hash += HASH_REFLECT * shade(depth, newImportance, ref origin, ref reflected, comp);
            if (ks.Length >= bands)
              for (int b = 0; b < bands; b++)
                color[b] += ks[b] * comp[b];
            else
              for (int b = 0; b < bands; b++)
                color[b] += ks[Math.Min(b, ks.Length - 1)] * comp[b];
          }
        }
      }
    }

    if (DoRefractions)
    {
      IMaterial material = i.Material!;
      double kt = Kt(material);
      if (FresnelRefraction && kt > 0.0)
        kt *= 1.0 - SchlickReflectance(Math.Abs(Vector3d.Dot(i.Normal, viewer)), Index(material));
      double newImportance = importance * kt;
      if (newImportance < MinImportance)
        goto done;
      Vector3d r = haveUnit
        ? Geometry.SpecularRefractionUnit(i.Normal, Index(material), viewerUnit)
        : Geometry.SpecularRefraction(i.Normal, Index(material), viewer);
      if (r.X == 0.0 && r.Y == 0.0 && r.Z == 0.0 || !RefractionDirection(i, r, depth, out r))
        goto done;
      if (observer != null)
        scratch.NextKind = RayKind.Refracted;
      hash += HASH_REFRACT * shade(depth, newImportance, ref origin, ref r, comp);
      AddScaled(color, comp, kt);
    }

  done:
    // Every way out passes here, so an observer sees the end of each ray it saw begin (the hit stays valid
    // until the next ray at this depth).
    observer?.EndRay(kind, rayDepth, p0, p1, i);
    return hash;
  }

  /// <summary>
  /// The direction of the reflected ray at hit <paramref name="i"/> (its recursion depth <paramref name="depth"/>),
  /// given the mirror direction; false = no reflected ray. Whitted: the mirror direction itself.
  /// <see cref="Distributed.DistributedRayTracing"/> samples a glossy lobe around it.
  /// </summary>
  protected virtual bool ReflectionDirection(Intersection i, Vector3d mirror, int depth, out Vector3d direction)
  {
    direction = mirror;
    return true;
  }

  /// <summary>The direction of the refracted ray, given the ideal one; false = no refracted ray. Whitted: the ideal direction.</summary>
  protected virtual bool RefractionDirection(Intersection i, Vector3d refracted, int depth, out Vector3d direction)
  {
    direction = refracted;
    return true;
  }

  /// <summary>Schlick's approximation of the Fresnel reflectance for incidence cosine <paramref name="cos"/>.</summary>
  public static double SchlickReflectance(double cos, double n)
  {
    double r0 = (n - 1.0) / (n + 1.0);
    r0 *= r0;
    double m = 1.0 - Math.Clamp(cos, 0.0, 1.0);
    return r0 + (1.0 - r0) * m * m * m * m * m;
  }

  /// <summary>Custom shading by the solid's <see cref="RecursionFunction"/>: the function's <see cref="RayRecursion"/> does the rest.</summary>
  long ShadeRecursion(RecursionFunction recursion, Intersection i, int depth, double importance, ref Vector3d p1, double[] color, long hash)
  {
    hash += HASH_RECURSION * recursion(i, p1, importance, out RayRecursion rr);
    return rr == null ? hash : rr.Recursion(this, i, hash, depth, color);
  }

  static void FillBackground(IRayScene sc, double[] color)
  {
    double[]? bg = sc.BackgroundColor;
    if (bg == null || bg.Length == 0)
    {
      Array.Clear(color);
      return;
    }
    for (int b = 0; b < color.Length; b++)
      color[b] = bg[Math.Min(b, bg.Length - 1)];
  }

  /// <summary>Zeroes a colour of a few bands inline (Array.Clear's call costs more than three stores).</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  internal static void Zero(double[] color)
  {
    for (int b = 0; b < color.Length; b++)
      color[b] = 0.0;
  }

  /// <summary>color += k · src; a one-element src adds the same value to every band.</summary>
  protected static void AddScaled(double[] color, double[] src, double k)
  {
    for (int b = 0; b < color.Length; b++)
      color[b] += k * src[Math.Min(b, src.Length - 1)];
  }
}
