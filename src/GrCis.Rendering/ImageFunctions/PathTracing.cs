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
/// background as an environment light. Every diffuse or glossy vertex samples the lights (next-event
/// estimation) and combines that with the scattered ray by multiple importance sampling (power heuristic);
/// paths end by Russian roulette from the second bounce on. Every random decision of a vertex (lobe, direction,
/// roulette, emitter, point on it) comes from the worker's <see cref="Sampler"/>, each in a <see cref="SampleDimension"/>
/// of its own. Output is linear radiance: render to PFM for comparisons, use n×n supersampling for the noise to fall.
/// </summary>
/// <remarks>
/// GrCis's light sources are points (or area lights sampled as points): a light of intensity I lights a
/// Lambertian surface of albedo a exactly as Whitted ray tracing does, a·I·cos θ, so it acts as irradiance π·I
/// per unit of cos θ. Ambient lights are ignored: the indirect light they stood for is computed.
/// </remarks>
[Serializable]
public class PathTracing : RayTracing
{
  /// <summary>Sample light sources and emissive rectangles and spheres at every diffuse or glossy vertex.</summary>
  public bool NextEventEstimation = true;

  /// <summary>Weigh light samples and scattered rays that reach an emitter by the power heuristic (else light samples alone count).</summary>
  public bool MultipleImportanceSampling = true;

  /// <summary>Bounces before Russian roulette may end a path (Cycles: the first bounce is never ended).</summary>
  public int RussianRouletteStart = 1;

  /// <summary>Phong exponents at or above this make an ideal mirror (a delta lobe).</summary>
  public int MirrorExponent = 100000;

  public PathTracing(IRayScene? sc = null) : base(sc) => MaxLevel = 64;

  /// <inheritdoc/>
  public override void CopySettingsFrom(RayCasting source)
  {
    base.CopySettingsFrom(source);
    if (source is not PathTracing p)
      return;
    NextEventEstimation = p.NextEventEstimation;
    MultipleImportanceSampling = p.MultipleImportanceSampling;
    RussianRouletteStart = p.RussianRouletteStart;
    MirrorExponent = p.MirrorExponent;
  }

  /// <summary>The emitters of the scene the worker renders, kept in its context and rebuilt when the scene, its snapshot or the frame changes.</summary>
  EmitterSet EmittersOf(WorkerContext context, IRayScene sc)
  {
    IIntersectable? root = sc.Intersectable;
    PreparedScene? snapshot = PreparedFor(context.Scratch);
    int frame = context.Sampler.Frame;
    if (context.Emitters is not EmitterSet emitters || !ReferenceEquals(context.EmittersRoot, root) ||
        !ReferenceEquals(context.EmittersSnapshot, snapshot) || context.EmittersFrame != frame)
    {
      context.Emitters = emitters = EmitterSet.Of(root);
      context.EmittersRoot = root;
      context.EmittersSnapshot = snapshot;
      context.EmittersFrame = frame;
    }
    return emitters;
  }

  /// <summary>Radiance arriving along the ray <c>p0 + t p1</c> by path tracing, into <paramref name="color"/>; returns the first hit's hash.</summary>
  public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    WorkerContext context = WorkerContext.Current;
    ShadingScratch scratch = context.Scratch;
    Sampler sampler = context.Sampler;
    IRayScene sc = Scene;
    EmitterSet lights = NextEventEstimation ? EmittersOf(context, sc) : EmitterSet.Empty;

    Rgb radiance = Rgb.Zero, throughput = Rgb.One;
    Vector3d origin = p0, direction = p1.Normalized();
    bool afterDelta = true;   // the camera ray, like a mirror bounce, cannot be found by light sampling
    double lastPdf = 0.0;
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
        radiance += throughput * Environment(sc, direction, scratch.Buffer(depth + 1, color.Length));
        break;
      }
      scratch.Hits++;
      long h = CompleteAndTexture(i);
      if (bounce == 0)
        hash = h;
      Vector3d x = i.CoordWorld;
      Vector3d normal = i.Normal;

      // Light leaving an emitter towards the ray, weighed against the light sample that could have found it.
      if (i.Material is PhongMaterial { Emission: double[] emission } && Vector3d.Dot(normal, direction) < 0.0)
      {
        double w = 1.0;
        // A light sample could not have found it when its density is 0 (a sphere seen from inside or on it).
        if (!afterDelta && lights.Pdf(i.Solid, origin, x, normal, direction, out double lightPdf) && lightPdf > 0.0)
          w = MultipleImportanceSampling ? PowerHeuristic(lastPdf, lightPdf) : 0.0;
        radiance += throughput * Rgb.From(emission) * w;
      }
      if (bounce >= MaxLevel)
        break;

      PathBsdf bsdf = PathBsdf.For(i.Material, i.SurfaceColor, normal, direction, MirrorExponent);
      if (!bsdf.Scatters)
        break;
      if (NextEventEstimation && bsdf.HasSmooth)
        radiance += throughput * SampleLights(scratch, sampler, sc, lights, i, bsdf, bounce);

      // Continue the path in a direction sampled from the surface's lobes.
      sampler.Get2D(SampleDimension.PathDirection, bounce, out double u, out double v);
      if (!bsdf.Sample(sampler.Get1D(SampleDimension.PathLobe, bounce), u, v, out Vector3d wi, out Rgb weight, out double pdf, out bool delta))
        break;
      throughput *= weight;
      if (throughput.IsBlack)
        break;
      if (bounce >= RussianRouletteStart)
      {
        double survive = Math.Min(1.0, Math.Sqrt(throughput.Max));
        if (sampler.Get1D(SampleDimension.PathRoulette, bounce) >= survive)
          break;
        throughput *= 1.0 / survive;
      }
      origin = x;
      direction = wi;
      afterDelta = delta;
      lastPdf = pdf;
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

  /// <summary>Ray <paramref name="index"/> of the path being observed (kept in the worker's context, ended in reverse order when the path is done).</summary>
  static ref (RayKind Kind, int Depth, Vector3d Origin, Vector3d Direction, Intersection? Hit) Observed(WorkerContext context, int index)
  {
    if (context.ObservedRays == null || index >= context.ObservedRays.Length)
      Array.Resize(ref context.ObservedRays, Math.Max(16, 2 * index));
    return ref context.ObservedRays![index];
  }

  /// <summary>Direct light at hit <paramref name="i"/>: every light source once, and one sample of one emitter.</summary>
  Rgb SampleLights(ShadingScratch scratch, Sampler sampler, IRayScene sc, EmitterSet lights, Intersection i, in PathBsdf bsdf, int bounce)
  {
    Rgb sum = Rgb.Zero;
    Vector3d x = i.CoordWorld;
    Vector3d nf = bsdf.FacingNormal;

    if (sc.Sources is { Count: > 0 } sources)
    {
      // Lights read the hit's normal to tell the lit side: give them the side this vertex scatters on.
      Vector3d outward = i.Normal;
      i.Normal = nf;
      if (sources is LinkedList<ILightSource> linked)
      {
        for (LinkedListNode<ILightSource>? n = linked.First; n != null; n = n.Next)
          sum += PointLight(scratch, n.Value, i, bsdf);
      }
      else
        foreach (ILightSource source in sources)
          sum += PointLight(scratch, source, i, bsdf);
      i.Normal = outward;
    }

    if (lights.Count > 0)
    {
      sampler.Get2D(SampleDimension.PathLightPoint, bounce, out double u, out double v);
      if (lights.Sample(x, sampler.Get1D(SampleDimension.PathLightPick, bounce), u, v, out Vector3d toLight, out double dist, out Vector3d wi, out Rgb le, out double lightPdf))
      {
        double cos = Vector3d.Dot(wi, nf);
        if (cos > 0.0)
        {
          Rgb f = bsdf.Eval(wi);
          if (!f.IsBlack && Visible(scratch, x, toLight, dist))
          {
            double w = MultipleImportanceSampling ? PowerHeuristic(lightPdf, bsdf.Pdf(wi)) : 1.0;
            sum += f * le * (cos * w / lightPdf);
          }
        }
      }
    }
    return sum;
  }

  /// <summary>One GrCis light source's contribution: irradiance π·I (see the class remarks), shadowed.</summary>
  Rgb PointLight(ShadingScratch scratch, ILightSource source, Intersection i, in PathBsdf bsdf)
  {
    double[]? intensity = source.GetIntensity(i, out Vector3d dir);
    if (intensity == null || (dir.X == 0.0 && dir.Y == 0.0 && dir.Z == 0.0))
      return Rgb.Zero;   // unlit, or ambient light
    double dist = dir.Length;
    Vector3d wi = dir / dist;
    double cos = Vector3d.Dot(wi, bsdf.FacingNormal);
    if (cos <= 0.0)
      return Rgb.Zero;
    Rgb f = bsdf.Eval(wi);
    if (f.IsBlack || !Visible(scratch, i.CoordWorld, dir, dist))
      return Rgb.Zero;
    return f * Rgb.From(intensity) * (Math.PI * cos);
  }

  /// <summary>True when nothing blocks the segment from <paramref name="x"/> to <c>x + toLight</c> (the light's own surface excluded).</summary>
  bool Visible(ShadingScratch scratch, Vector3d x, Vector3d toLight, double dist)
  {
    if (!DoShadows)
      return true;
    // Stop short of the light's surface, so that surface is not taken for an occluder.
    double keep = 1.0 - 4.0 * Intersection.RAY_EPSILON / dist;
    bool visible = keep <= 0.0 || !Blocked(scratch, x, toLight * keep);
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
