using System;
using System.Collections.Generic;
using MathSupport;
using OpenTK.Mathematics;
using Rendering.Execution;
using Rendering.Observation;

namespace Rendering;

/// <summary>
/// Whitted ray tracing. A ray from the camera finds the nearest surface; the surface is lit by every light source
/// that is not hidden behind another solid (a shadow ray tests that), using the surface's reflectance model (Phong);
/// then a mirrored ray and a refracted ray are traced recursively from the hit and their colours added, weighted by
/// the material's reflection and transmission coefficients. The recursion stops at depth <see cref="MaxLevel"/> or
/// when a ray's importance (how much it can still change the pixel) falls below <see cref="MinImportance"/>. Solids
/// with a <see cref="PropertyName.RECURSION"/> attribute shade themselves (<see cref="RecursionFunction"/>).
/// <para>
/// <see cref="shade"/> is the algorithm; subclasses override it, <see cref="Occluded"/>, or the directions of the
/// secondary rays (<see cref="ReflectionDirection"/>, <see cref="RefractionDirection"/>). The renderer samples this
/// class, and subclasses that change none of the shading, through a prepared kernel that computes the same
/// colours and hashes faster (<c>Rendering.Accel.WhittedKernel</c>); the image is the same either way.
/// </para>
/// </summary>
[Serializable]
public class RayTracing : RayCasting
{
  /// <summary>Factor of the path hash for a refracted ray (the hash tells apart pixels that saw different things).</summary>
  protected internal const long HASH_REFRACT = 13L;

  /// <summary>Factor of the path hash for a reflected ray.</summary>
  protected internal const long HASH_REFLECT = 17L;

  /// <summary>Factor of the path hash for a solid's own <see cref="RecursionFunction"/>.</summary>
  protected internal const long HASH_RECURSION = 101L;

  /// <summary>Maximal depth of secondary rays: the camera's ray is depth 0, each reflection or refraction adds one. Default 12.</summary>
  public int MaxLevel = 12;

  /// <summary>
  /// Secondary rays whose importance (the product of the reflection or transmission coefficients along the path,
  /// 1 for the camera's ray) is below this are not traced. Default 0.05.
  /// </summary>
  public double MinImportance = 0.05;

  /// <summary>Cast shadow rays: a light hidden behind a solid does not light the surface. Default true.</summary>
  public bool DoShadows = true;

  /// <summary>Trace mirrored (reflected) rays. Default true.</summary>
  public bool DoReflections = true;

  /// <summary>Trace refracted (transmitted) rays. Default true.</summary>
  public bool DoRefractions = true;

  /// <summary>Let solids with a <see cref="PropertyName.RECURSION"/> attribute shade themselves. Default true.</summary>
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

  /// <summary>Receives every ray traced, when set (GrCis's 048 ray visualiser API); null costs nothing.</summary>
  [NonSerialized]
  public AbstractRayRegisterer? rayRegisterer;

  /// <summary>A Whitted ray tracer of scene <paramref name="sc"/> (null: the scene being rendered, <see cref="MT.scene"/>).</summary>
  public RayTracing(IRayScene? sc = null) : base(sc)
  {
  }

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

  /// <summary>
  /// The colour of image point (<paramref name="x"/>, <paramref name="y"/>) (in pixels, from the top left corner):
  /// the camera's ray through it, shaded. Returns the path hash (11 when the camera gives no ray).
  /// </summary>
  public override long GetSample(double x, double y, double[] color)
  {
    MT.doubleX = x;
    MT.doubleY = y;
    Array.Clear(color);
    ICamera? camera = Scene.Camera;
    if (camera == null || !camera.GetRay(x, y, out Vector3d p0, out Vector3d p1))
      return 11L;
    return shade(0, 1.0, ref p0, ref p1, color);
  }

  /// <summary>
  /// The colour seen along the ray from <paramref name="p0"/> in direction <paramref name="p1"/>, written to
  /// <paramref name="color"/>: Whitted's recursive algorithm. <paramref name="depth"/> is the recursion depth (0 for
  /// the camera's ray), <paramref name="importance"/> how much this ray can still change the pixel (1 for the
  /// camera's ray). Returns a hash of what the ray saw (solids, textures, lights), which adaptive supersampling
  /// compares between neighbouring samples.
  /// </summary>
  public virtual long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    // Report the ray to an observer (the pixel probe, the ray views), when one listens.
    ShadingScratch scratch = ShadingScratch.Current;
    RayKind kind = scratch.BeginRay(depth, p0, p1);

    // The nearest surface along the ray.
    Intersection? i = FirstHitAt(depth, p0, p1);
    long hash = i == null
      ? ShadeBackground(depth, p0, p1, color)
      : ShadeSurface(i, depth, importance, p0, p1, color);

    scratch.EndRay(kind, depth, p0, p1, i);
    return hash;
  }

  /// <summary>A ray that hits nothing sees the background.</summary>
  long ShadeBackground(int depth, Vector3d p0, Vector3d p1, double[] color)
  {
    rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerNormal, depth, p0, p1 * 100000.0);
    IBackground? background = Scene.Background;
    return background != null ? background.GetColor(p1, color) : FillBackground(Scene, color);
  }

  /// <summary>The colour of the surface hit <paramref name="i"/> seen along the ray: local lighting, then the mirrored and refracted rays.</summary>
  long ShadeSurface(Intersection i, int depth, double importance, Vector3d p0, Vector3d p1, double[] color)
  {
    RayCounter.CountHit();
    // Everything about the hit: point, normal, material, textures applied (they may change the colour or the normal).
    long hash = CompleteAndTexture(i);
    rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.unknown, depth, p0, i);
    Array.Clear(color);

    // A solid may shade itself (glow, custom recursion).
    if (DoRecursion && i.RecursionAttribute is RecursionFunction recursion)
    {
      hash += HASH_RECURSION * recursion(i, p1, importance, out RayRecursion rr);
      return rr == null ? hash : rr.Recursion(this, i, hash, depth, color);
    }

    Vector3d viewer = -p1.Normalized();   // from the surface towards the eye
    double[] surface = i.SurfaceColor!;

    // 1. Local lighting: every light source that sees the point, through the reflectance model.
    ICollection<ILightSource>? sources = Scene.Sources;
    if (sources == null || sources.Count == 0)
      AddScaled(color, surface, 1.0);   // no lights: the surface colour as it is
    else
    {
      // The material with the (textured) surface colour: GrCis clones it per hit, a per-depth copy here.
      i.Material = ShadingScratch.Current.Material(i.Material!, surface, depth);
      foreach (ILightSource source in sources)
        hash = AddLight(source, i, viewer, color, hash);
    }

    // 2. Recursion: stop at the maximal depth.
    if (depth++ >= MaxLevel || (!DoReflections && !DoRefractions))
      return hash;
    double[] comp = ShadingScratch.Current.Buffer(depth, color.Length);   // a secondary ray's colour
    Vector3d origin = i.CoordWorld;

    // 3. The mirrored ray, weighted by the specular reflectance.
    if (DoReflections)
    {
      Vector3d r = Geometry.SpecularReflection(i.Normal, viewer);
      double[]? ks = i.ReflectanceModel!.ColorReflection(i, viewer, r, ReflectionComponent.SPECULAR_REFLECTION);
      if (ks != null)
      {
        double newImportance = importance * Max(ks);
        if (newImportance >= MinImportance && ReflectionDirection(i, r, depth, out Vector3d reflected))
        {
          ShadingScratch.Current.NextRay(RayKind.Reflected);
          hash += HASH_REFLECT * shade(depth, newImportance, ref origin, ref reflected, comp);
          for (int b = 0; b < color.Length; b++)
            color[b] += ks[Math.Min(b, ks.Length - 1)] * comp[b];
        }
      }
    }

    // 4. The refracted ray, weighted by the transmission coefficient Kt.
    if (DoRefractions)
    {
      IMaterial material = i.Material!;
      double kt = material.Kt;
      if (FresnelRefraction && kt > 0.0)
        kt *= 1.0 - SchlickReflectance(Math.Abs(Vector3d.Dot(i.Normal, viewer)), material.n);
      double newImportance = importance * kt;
      if (newImportance < MinImportance)
        return hash;
      Vector3d r = Geometry.SpecularRefraction(i.Normal, material.n, viewer);
      if (r == Vector3d.Zero || !RefractionDirection(i, r, depth, out r))   // zero: total internal reflection
        return hash;
      ShadingScratch.Current.NextRay(RayKind.Refracted);
      hash += HASH_REFRACT * shade(depth, newImportance, ref origin, ref r, comp);
      AddScaled(color, comp, kt);
    }
    return hash;
  }

  /// <summary>
  /// Adds the light of <paramref name="source"/> reflected at hit <paramref name="i"/> towards
  /// <paramref name="viewer"/> to <paramref name="color"/>, unless a solid casts a shadow; returns the hash.
  /// </summary>
  long AddLight(ILightSource source, Intersection i, Vector3d viewer, double[] color, long hash)
  {
    // The light's intensity at the point and the direction to it (zero for an ambient light).
    double[]? intensity = source.GetIntensity(i, out Vector3d dir);
    if (rayRegisterer != null && MT.singleRayTracing && source.position is Vector3d lightPosition)
      rayRegisterer.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerShadow, i.CoordWorld, lightPosition);
    if (intensity == null)
      return hash;

    // The shadow ray: is anything between the point and the light?
    double transmit = 1.0;
    if (DoShadows && dir != Vector3d.Zero)
    {
      if (TransparentShadows)
      {
        RayCounter.CountRay();
        transmit = ShadowTransmittance(i.CoordWorld, dir);
      }
      else
        transmit = Occluded(i.CoordWorld, dir) ? 0.0 : 1.0;
      ShadingScratch.Current.Observer?.ShadowRay(i.CoordWorld, dir, transmit <= 0.0);
      if (transmit <= 0.0)
      {
        RayCounter.CountHit();   // a blocked shadow ray
        return hash;
      }
    }

    // The reflectance model: how much of the light goes towards the viewer.
    double[]? reflection = i.ReflectanceModel!.ColorReflection(i, dir, viewer, ReflectionComponent.ALL);
    if (reflection == null)
      return hash;
    for (int b = 0; b < color.Length; b++)
      color[b] += transmit * intensity[Math.Min(b, intensity.Length - 1)] * reflection[Math.Min(b, reflection.Length - 1)];
    return hash * HASH_LIGHT + source.GetHashCode();
  }

  // Names of the virtuals that see hits or decide the shading (RayCasting.HitReaders, LibraryTypes.ShadesAsWhitted).
  internal const string ShadeName = nameof(shade), OccludedName = nameof(Occluded), ShadowTransmittanceName = nameof(ShadowTransmittance);

  /// <summary>
  /// True when something (not marked <see cref="PropertyName.NO_SHADOW"/>) lies between the point
  /// <paramref name="p0"/> and the light at <c>p0 + dir</c>: the shadow ray.
  /// </summary>
  protected virtual bool Occluded(Vector3d p0, Vector3d dir)
  {
    RayCounter.CountRay();
    return Query.AnyHit(p0, dir);
  }

  /// <summary>
  /// Fraction of light passing from <paramref name="p0"/> to the light at <c>p0 + dir</c>: the product
  /// of the Kt of every surface entered on the way (0 = blocked). Uses the faithful all-hits query.
  /// </summary>
  protected internal virtual double ShadowTransmittance(Vector3d p0, Vector3d dir)
  {
    LinkedList<Intersection>? list = IntersectScene(p0, dir);
    if (list == null)
      return 1.0;
    double transmit = 1.0;
    double len2 = dir.LengthSquared;
    bool first = true;
    foreach (Intersection hit in list)
    {
      if (hit.T <= 0.0 || hit.T * hit.T * len2 <= Intersection.RAY_EPSILON2)
        continue;
      if (hit.Far(1.0, ref dir))
        break;
      if (hit.Solid != null && hit.Solid.GetLocalAttribute(PropertyName.NO_SHADOW) != null)
        continue;
      // Count each solid once: where the ray enters it, or at its exit when the ray starts inside.
      if (hit.Enter || first)
      {
        double kt = (hit.Solid?.GetAttribute(PropertyName.MATERIAL) as IMaterial)?.Kt ?? 0.0;
        transmit *= kt;
        if (transmit <= 0.0)
          return 0.0;
      }
      first = false;
    }
    return transmit;
  }

  /// <summary>
  /// The direction of the reflected ray at hit <paramref name="i"/> (its recursion depth <paramref name="depth"/>),
  /// given the mirror direction; false = no reflected ray. Whitted: the mirror direction itself.
  /// <see cref="Distributed.DistributedRayTracing"/> samples a glossy lobe around it.
  /// </summary>
  protected internal virtual bool ReflectionDirection(Intersection i, Vector3d mirror, int depth, out Vector3d direction)
  {
    direction = mirror;
    return true;
  }

  /// <summary>The direction of the refracted ray, given the ideal one; false = no refracted ray. Whitted: the ideal direction.</summary>
  protected internal virtual bool RefractionDirection(Intersection i, Vector3d refracted, int depth, out Vector3d direction)
  {
    direction = refracted;
    return true;
  }

  /// <summary>
  /// Schlick's approximation of the Fresnel reflectance of an interface with relative index of refraction
  /// <paramref name="n"/>, for incidence cosine <paramref name="cos"/> (1 = along the normal).
  /// </summary>
  public static double SchlickReflectance(double cos, double n)
  {
    double r0 = (n - 1.0) / (n + 1.0);
    r0 *= r0;
    double m = 1.0 - Math.Clamp(cos, 0.0, 1.0);
    return r0 + (1.0 - r0) * m * m * m * m * m;
  }

  /// <summary>The scene's <see cref="IRayScene.BackgroundColor"/> (black when it has none), for a scene without a background object; returns the hash 1.</summary>
  internal static long FillBackground(IRayScene sc, double[] color)
  {
    double[]? bg = sc.BackgroundColor;
    if (bg == null || bg.Length == 0)
      Array.Clear(color);
    else
      for (int b = 0; b < color.Length; b++)
        color[b] = bg[Math.Min(b, bg.Length - 1)];
    return 1L;
  }

  /// <summary>The largest of the bands (the importance a reflectance passes on).</summary>
  static double Max(double[] bands)
  {
    double max = bands[0];
    for (int b = 1; b < bands.Length; b++)
      max = Math.Max(max, bands[b]);
    return max;
  }

  /// <summary>color += k · src; a one-element src adds the same value to every band.</summary>
  protected static void AddScaled(double[] color, double[] src, double k)
  {
    for (int b = 0; b < color.Length; b++)
      color[b] += k * src[Math.Min(b, src.Length - 1)];
  }
}
