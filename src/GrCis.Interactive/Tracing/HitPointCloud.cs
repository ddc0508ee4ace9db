using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;
using Rendering.Observation;

using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// The points where a render's primary rays hit (GrCis's 048 visualiser's hit point cloud): one ray through the centre of
/// every <see cref="Step"/>-th pixel in each direction, traced as the pixel probe traces one (<see cref="PixelProbe"/>: on
/// a worker of its own over the job's scene and queries, seeded as the renderer seeds the pixel, the primary ray's hit
/// reported to an observer), so the points lie on what the render saw, a CSG result or a script's own solid included.
/// Deterministic: the same job gives the same points.
/// </summary>
public sealed class HitPointCloud
{
  HitPointCloud(int step, int rays, IReadOnlyList<HitPoint> points)
  {
    Step = step;
    Rays = rays;
    Points = points;
  }

  /// <summary>Pixels between two rays, in x and in y (1 = every pixel).</summary>
  public int Step { get; }

  /// <summary>How many rays were cast (the points are those that hit something).</summary>
  public int Rays { get; }

  /// <summary>The hits, row by row.</summary>
  public IReadOnlyList<HitPoint> Points { get; }

  /// <summary>Casts at most <paramref name="maxRays"/> primary rays of <paramref name="job"/> on an even grid of its pixels.</summary>
  /// <param name="rendered">The job's image, whose pixels colour the points; null = each ray's own sample colour (for a library
  /// image function, ray casting's: the surface lit, without shadows or reflections).</param>
  public static HitPointCloud Cast(RenderJob job, int maxRays, FloatImage? rendered = null)
  {
    ArgumentNullException.ThrowIfNull(job);
    ArgumentOutOfRangeException.ThrowIfLessThan(maxRays, 1);
    int width = job.Width, height = job.Height;
    // The smallest step whose grid has at most maxRays points.
    int step = Math.Max(1, (int)Math.Sqrt((double)width * height / maxRays));
    while ((long)Across(width, step) * Across(height, step) > maxRays)
      step++;
    if (rendered != null && (rendered.Width != width || rendered.Height != height))
      rendered = null;

    var points = new List<HitPoint>();
    int rays = 0;
    var observer = new PrimaryHit();
    IImageFunction tracer = PrimaryTracer(job.ImageFunction);
    using (WorkerContext.Begin(null, job.Scene, tracer, job.Renderer, job.Options))
    using (new RenderContext { Observer = observer }.Enter())
    {
      double[] sample = new double[rendered?.Bands ?? 3];
      double[] pixel = new double[sample.Length];
      // Each grid cell's middle pixel, so the points spread evenly over the image.
      for (int y = step / 2; y < height; y += step)
        for (int x = step / 2; x < width; x += step)
        {
          observer.Reset();
          MT.StartPixel(x, y, 1);
          tracer.GetSample(x + 0.5, y + 0.5, sample);
          rays++;
          if (observer.Hit is not Vector3d hit)
            continue;
          double[] color = sample;
          if (rendered != null)
          {
            rendered.GetPixel(x, y, pixel);
            color = pixel;
          }
          points.Add(new HitPoint(x, y, hit, Rgb(color), observer.Solid));
        }
    }
    return new HitPointCloud(step, rays, points);
  }

  /// <summary>
  /// What traces the primary rays. The library's image functions all take their primary ray from the camera and its
  /// first hit from the same query, so plain ray casting with the function's settings finds the same hits without
  /// shading the reflections, refractions and paths behind them (a glass ball's ray tree costs 10× its primary ray). A
  /// script's own subclass may trace otherwise and is asked itself; a function that is not a RayCasting reports no
  /// rays, and ray casting stands in for it (as <see cref="ExtraViews"/> does).
  /// </summary>
  static IImageFunction PrimaryTracer(IImageFunction function)
  {
    if (function is not RayCasting own)
      return new RayCasting();
    if (own.GetType().Assembly != typeof(RayCasting).Assembly)
      return function;
    var plain = new RayCasting();
    plain.CopySettingsFrom(own);
    return plain;
  }

  static int Across(int size, int step) => (size - step / 2 + step - 1) / step;

  static Vector3d Rgb(double[] c) => c.Length >= 3 ? new Vector3d(c[0], c[1], c[2]) : new Vector3d(c[0]);

  /// <summary>The first hit of the sample's primary ray (depth 0), copied: the hit object may be reused by the next ray.</summary>
  sealed class PrimaryHit : RayObserver
  {
    public Vector3d? Hit;
    public ISolid? Solid;
    bool seen;

    public void Reset()
    {
      Hit = null;
      Solid = null;
      seen = false;
    }

    public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
    {
      if (seen || kind != RayKind.Primary || depth != 0)
        return;
      seen = true;
      if (hit != null)
      {
        Hit = hit.CoordWorld;
        Solid = hit.Solid;
      }
    }
  }
}
