using System;
using System.Collections.Generic;
using MathSupport;
using OpenTK.Mathematics;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Observation;

namespace Rendering;

/// <summary>
/// Monte Carlo path tracing on GrCis's scene graph: global illumination with the scattering of
/// <see cref="PathBsdf"/> (Lambertian, normalised Phong, ideal mirror, smooth dielectric, read from the
/// Phong parameters), emissive surfaces (<see cref="PhongMaterial.Emission"/>), GrCis's light sources and the
/// background as an environment light, all through one light model (<see cref="ILight"/>, <see cref="SceneLights"/>).
/// Every diffuse or glossy vertex samples each delta light and one light a ray can also hit, chosen by power (next-event
/// estimation), and combines the latter with the scattered ray by multiple importance sampling (power heuristic);
/// paths end by Russian roulette from the second bounce on, at vertices that scattered through a smooth lobe. Every random decision of a vertex (lobe, direction,
/// roulette, emitter, point on it) comes from the worker's <see cref="Sampler"/>, each in a <see cref="SampleDimension"/>
/// of its own. Output is linear radiance: render to PFM for comparisons, use n×n supersampling for the noise to fall.
/// </summary>
/// <remarks>
/// GrCis's light sources are points (or area lights sampled as points): a light of intensity I lights a
/// Lambertian surface of albedo a exactly as Whitted ray tracing does, a·I·cos θ, so it acts as irradiance π·I
/// per unit of cos θ. Ambient lights are ignored: the indirect light they stood for is computed.
/// </remarks>
[Serializable]
public class PathTracing : MonteCarloRayTracing
{
  /// <summary>Sample light sources and emissive rectangles and spheres at every diffuse or glossy vertex.</summary>
  public bool NextEventEstimation = true;

  /// <summary>Weigh light samples and scattered rays that reach an emitter by the power heuristic (else light samples alone count).</summary>
  public bool MultipleImportanceSampling = true;

  /// <summary>
  /// Sample the background as a light too (cosine-weighted, MIS against the scattered rays). Off by default: on the
  /// built-in scenes it measured 1–5 % more error per sample than finding the background by scattered rays alone.
  /// </summary>
  public bool EnvironmentSampling = false;

  /// <summary>Bounces before Russian roulette may end a path (Cycles: the first bounce is never ended); it never ends one after a mirror or dielectric scattering.</summary>
  public int RussianRouletteStart = 1;

  /// <summary>Phong exponents at or above this make an ideal mirror (a delta lobe).</summary>
  public int MirrorExponent = 100000;

  /// <summary>Path tracing of <paramref name="sc"/> with paths up to 64 vertices deep (<see cref="RayTracing.MaxLevel"/>).</summary>
  /// <param name="sc">The scene, or null to render the current scene (<see cref="MT.scene"/>).</param>
  public PathTracing(IRayScene? sc = null) : base(sc) => MaxLevel = 64;

  /// <summary>False: a path scatters by the materials at every bounce, whatever --no-reflections and --no-refractions say.</summary>
  public override bool FollowsRayTypeSwitches => false;

  /// <inheritdoc/>
  public override void CopySettingsFrom(RayCasting source)
  {
    base.CopySettingsFrom(source);
    if (source is not PathTracing p)
      return;
    NextEventEstimation = p.NextEventEstimation;
    MultipleImportanceSampling = p.MultipleImportanceSampling;
    RussianRouletteStart = p.RussianRouletteStart;
    EnvironmentSampling = p.EnvironmentSampling;
    MirrorExponent = p.MirrorExponent;
  }

  /// <summary>What a path tracer keeps per worker (<see cref="WorkerContext"/>): the lights of the scene it renders, rebuilt when the scene, its lights, its snapshot or the frame changes, and the rays of the path being observed.</summary>
  sealed class WorkerState
  {
    public SceneLights? Lights;
    public object? Scene, Sources, Root, Snapshot;
    public int Frame;
    public (RayKind Kind, int Depth, Vector3d Origin, Vector3d Direction, Intersection? Hit)[]? ObservedRays;
  }

  static readonly WorkerSlot<WorkerState> workerState = new(() => new WorkerState());

  /// <summary>The lights of the scene the worker renders, kept in its context and rebuilt when the scene, its lights, its snapshot or the frame changes.</summary>
  SceneLights LightsOf(WorkerContext context, IRayScene sc, int bands)
  {
    IIntersectable? root = sc.Intersectable;
    PreparedScene? snapshot = PreparedFor(ShadingScratch.Of(context));
    int frame = context.Sampler.Frame;
    object? sources = sc.Sources;
    WorkerState w = context.Get(workerState);
    if (w.Lights is not SceneLights lights || lights.SamplesEnvironment != EnvironmentSampling || !ReferenceEquals(w.Scene, sc) || !ReferenceEquals(w.Sources, sources) ||
        !ReferenceEquals(w.Root, root) || !ReferenceEquals(w.Snapshot, snapshot) || w.Frame != frame)
    {
      w.Lights = lights = SceneLights.Of(sc, root, bands, EnvironmentSampling);
      w.Scene = sc;
      w.Sources = sources;
      w.Root = root;
      w.Snapshot = snapshot;
      w.Frame = frame;
    }
    return lights;
  }

  /// <summary>Radiance arriving along the ray <c>p0 + t p1</c> by path tracing, into <paramref name="color"/>; returns the first hit's hash.</summary>
  public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    WorkerContext context = WorkerContext.Current;
    ShadingScratch scratch = ShadingScratch.Of(context);
    Sampler sampler = context.Sampler;
    IRayScene sc = Scene;
    SceneLights lights = LightsOf(context, sc, color.Length);

    Rgb radiance = Rgb.Zero, throughput = Rgb.One;
    Vector3d origin = p0, direction = p1.Normalized();
    bool afterDelta = true;   // the camera ray, like a mirror bounce, cannot be found by light sampling
    double lastPdf = 0.0;
    Vector3d lastNormal = default;   // the facing normal of the vertex the ray left (the environment's density reads it)
    long hash = 1L;

    // An observer (the demo's probe and extra views) sees the path as a chain: each bounce nests in the one before.
    RayObserver? observer = scratch.Observer;
    RayKind kind = RayKind.Primary;
    int observed = 0;
    if (observer != null)
    {
      kind = depth == 0 ? RayKind.Primary : scratch.NextKind;
      scratch.NextKind = RayKind.Secondary;
    }

    for (int bounce = 0; ; bounce++)
    {
      Intersection? i;
      if (observer == null)
        i = FirstHitAt(scratch, depth, origin, direction);
      else
      {
        // Each bounce fills a pooled hit of its own depth, so every hit is still valid when the chain ends.
        observer.BeginRay(kind, depth + bounce, origin, direction);
        i = FirstHitAt(scratch, depth + bounce, origin, direction);
        Observed(context, observed++) = (kind, depth + bounce, origin, direction, i);
      }
      if (i == null)
      {
        Rgb env = Environment(sc, direction, scratch.Buffer(depth + 1, color.Length));
        double w = 1.0;
        if (!afterDelta && NextEventEstimation && !env.IsBlack)
        {
          double lightPdf = lights.EnvironmentPdf(new LightContext(origin, lastNormal, null), direction);
          if (lightPdf > 0.0)
            w = MultipleImportanceSampling ? PowerHeuristic(lastPdf, lightPdf) : 0.0;
        }
        radiance += throughput * env * w;
        break;
      }
      scratch.Hits++;
      // Only the first hit's hash is returned: later hits are completed and textured without hashing their solid.
      if (bounce == 0)
        hash = CompleteAndTexture(i);
      else
        CompleteAndTextureUnhashed(i);
      Vector3d x = i.CoordWorld;
      Vector3d normal = i.Normal;

      // Light leaving an emitter towards the ray (from the light model), weighed against the light sample that could have found it.
      Rgb le = lights.Emitted(i, direction, out ILight? emitter);
      if (!le.IsBlack)
      {
        double w = 1.0;
        // A light sample could not have found it when its density is 0 (not a sampled light, a sphere seen from inside or on it).
        if (!afterDelta && NextEventEstimation)
        {
          double lightPdf = lights.Pdf(emitter!, new LightContext(origin, lastNormal, null), direction, x, normal);
          if (lightPdf > 0.0)
            w = MultipleImportanceSampling ? PowerHeuristic(lastPdf, lightPdf) : 0.0;
        }
        radiance += throughput * le * w;
      }
      if (bounce >= MaxLevel)
        break;

      // A material may supply its own scattering (IScatteringMaterial); else its Phong parameters decide.
      IMaterial? material = i.Material;
      PathBsdf bsdf = PathBsdf.For(material, i, PathBsdf.HasOwnScattering(material) ? scratch.Buffer(depth + 2, color.Length) : null, i.SurfaceColor, normal, direction, MirrorExponent);
      if (!bsdf.Scatters)
        break;
      if (NextEventEstimation && bsdf.HasSmooth)
        radiance += throughput * SampleLight(scratch, sampler, lights, i, bsdf, bounce, depth + (observer != null ? bounce : 0) + 1);

      // Continue the path in a direction sampled from the surface's lobes.
      double u = 0.0, v = 0.0;
      if (bsdf.SamplesDirection)
        sampler.Get2D(SampleDimension.PathDirection, bounce, out u, out v);
      // A surface of one lobe needs no lobe choice (any value picks it; the other dimensions do not depend on asking).
      double lobe = bsdf.SingleLobe ? 0.0 : sampler.Get1D(SampleDimension.PathLobe, bounce);
      if (!bsdf.Sample(lobe, u, v, out Vector3d wi, out Rgb weight, out double pdf, out bool delta))
        break;
      throughput *= weight;
      if (throughput.IsBlack)
        break;
      if (!Survives(sampler, bounce, delta, ref throughput))
        break;
      origin = x;
      direction = wi;
      afterDelta = delta;
      lastPdf = pdf;
      lastNormal = bsdf.FacingNormal;
      kind = Vector3d.Dot(wi, bsdf.FacingNormal) < 0.0 ? RayKind.Refracted : RayKind.Reflected;
    }
    while (observed > 0)
    {
      var (k, d, o, dir, hit) = Observed(context, --observed);
      observer!.EndRay(k, d, o, dir, hit);
    }
    radiance.CopyTo(color);
    return hash;
  }

  /// <summary>
  /// Russian roulette after the scattering at <paramref name="bounce"/>: from <see cref="RussianRouletteStart"/> on, and
  /// not after a mirror or dielectric (delta) scattering. Such a vertex keeps the throughput, so the roulette there
  /// would save little work but multiply the second moment of what the path still carries (caustics through glass, the
  /// light seen in a mirror) by 1/survival at every such vertex; a path ends at its next smooth vertex instead.
  /// </summary>
  internal bool Survives(Sampler sampler, int bounce, bool delta, ref Rgb throughput) =>
    bounce < RussianRouletteStart || delta || Roulette(sampler, bounce, ref throughput);

  /// <summary><see cref="RayCasting.CompleteAndTexture"/> without the hash: the same completion and texture calls, in the same order.</summary>
  static void CompleteAndTextureUnhashed(Intersection i)
  {
    i.Complete();
    if (i.Textures != null)
      foreach (ITexture tex in i.Textures)
        tex.Apply(i);
  }

  /// <summary>Ray <paramref name="index"/> of the path being observed (kept in the worker's context, ended in reverse order when the path is done).</summary>
  static ref (RayKind Kind, int Depth, Vector3d Origin, Vector3d Direction, Intersection? Hit) Observed(WorkerContext context, int index)
  {
    WorkerState w = context.Get(workerState);
    if (w.ObservedRays == null || index >= w.ObservedRays.Length)
      Array.Resize(ref w.ObservedRays, Math.Max(16, 2 * index));
    return ref w.ObservedRays![index];
  }

  /// <summary>
  /// Direct light at hit <paramref name="i"/> (next-event estimation): every delta light once (GrCis's light sources,
  /// which no ray can hit), then one of the lights a ray may also hit (emissive surfaces, the background), chosen by
  /// power and weighed by MIS against the scattered ray. <paramref name="slot"/> is the pooled hit a ray towards the
  /// background may fill.
  /// </summary>
  Rgb SampleLight(ShadingScratch scratch, Sampler sampler, SceneLights lights, Intersection i, in PathBsdf bsdf, int bounce, int slot)
  {
    Rgb sum = Rgb.Zero;
    var ctx = new LightContext(i.CoordWorld, bsdf.FacingNormal, i);
    ILight[] deltas = lights.DeltaLights;
    for (int k = 0; k < deltas.Length; k++)
    {
      sampler.Get2D(SampleDimension.PathDeltaLight, bounce * deltas.Length + k, out double du, out double dv);
      sum += Direct(scratch, deltas[k], ctx, bsdf, du, dv, 1.0, slot);
    }
    // One light to choose from needs no choice.
    LightSampler choose = lights.Sampler;
    ILight? light = choose.Sample(choose.Count > 1 ? sampler.Get1D(SampleDimension.PathLightPick, bounce) : 0.0, out double pick);
    if (light == null)
      return sum;
    sampler.Get2D(SampleDimension.PathLightPoint, bounce, out double u, out double v);
    return sum + Direct(scratch, light, ctx, bsdf, u, v, pick, slot);
  }

  /// <summary>One sample (u, v) of <paramref name="light"/>, chosen with probability <paramref name="pick"/>, seen from <paramref name="ctx"/>.</summary>
  Rgb Direct(ShadingScratch scratch, ILight light, in LightContext ctx, in PathBsdf bsdf, double u, double v, double pick, int slot)
  {
    if (!light.SampleLi(ctx, u, v, out LightSample s) || s.L.IsBlack)
      return Rgb.Zero;
    double cos = Vector3d.Dot(s.Wi, ctx.N);
    if (cos <= 0.0)
      return Rgb.Zero;
    // ctx.N is the BSDF's facing normal: the direction is above the surface, which Eval and Pdf need not test again.
    Rgb f = bsdf.EvalAbove(s.Wi);
    if (f.IsBlack)
      return Rgb.Zero;
    LightKind kind = light.Kind;
    if (kind == LightKind.DeltaPosition)
      return Visible(scratch, ctx.P, s.ToLight, s.Distance) ? f * s.L * (cos / pick) : Rgb.Zero;
    bool visible = kind == LightKind.Infinite ? Escapes(scratch, slot, ctx.P, s.Wi) : Visible(scratch, ctx.P, s.ToLight, s.Distance);
    if (!visible)
      return Rgb.Zero;
    double lightPdf = pick * s.Pdf;
    double w = MultipleImportanceSampling ? PowerHeuristic(lightPdf, bsdf.PdfAbove(s.Wi, cos)) : 1.0;
    return f * s.L * (cos * w / lightPdf);
  }

  /// <summary>True when the ray from <paramref name="x"/> along <paramref name="wi"/> leaves the scene (reaches the background).</summary>
  bool Escapes(ShadingScratch scratch, int slot, Vector3d x, Vector3d wi)
  {
    if (!DoShadows)
      return true;
    bool escapes = FirstHitAt(scratch, slot, x, wi) == null;
    scratch.Observer?.ShadowRay(x, wi, !escapes);
    return escapes;
  }

  /// <summary>True when nothing blocks the segment from <paramref name="x"/> to <c>x + toLight</c> (the light's own surface excluded).</summary>
  bool Visible(ShadingScratch scratch, Vector3d x, Vector3d toLight, double dist)
  {
    if (!DoShadows)
      return true;
    // Stop short of the light's surface, so that surface is not taken for an occluder.
    double keep = 1.0 - 4.0 * Intersection.RAY_EPSILON / dist;
    bool visible = keep <= 0.0 || !Occluded(x, toLight * keep);
    scratch.Observer?.ShadowRay(x, toLight, !visible);
    return visible;
  }

  /// <summary>Radiance of the background seen in <paramref name="direction"/>.</summary>
  static Rgb Environment(IRayScene sc, Vector3d direction, double[] buffer)
  {
    if (sc.Background != null)
    {
      sc.Background.GetColor(direction, buffer);
      return Rgb.From(buffer);
    }
    return sc.BackgroundColor is double[] bg ? Rgb.From(bg) : Rgb.Zero;
  }

  static double PowerHeuristic(double a, double b)
  {
    double a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
  }
}
