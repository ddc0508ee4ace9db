using System;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Observation;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class PixelProbeTests
{
  static readonly RenderSettings Odd = new() { Width = 101, Height = 101, Threads = 2 };

  static void Near(Vector3d expected, Vector3d? actual, double tol = 1e-9)
  {
    Assert.NotNull(actual);
    Assert.True((expected - actual!.Value).Length < tol, $"expected {expected}, got {actual}");
  }

  /// <summary>The camera ray of the centre pixel hits the sphere's front, whose shadow ray reaches the light unblocked.</summary>
  static RayNode CentreHitWithItsShadowRay(ProbeResult probe)
  {
    RayNode root = Assert.IsType<RayNode>(probe.Rays);
    Assert.Equal(RayKind.Primary, root.Kind);
    Near(new Vector3d(0, 0, -5), root.Origin);
    Near(Vector3d.UnitZ, root.Direction.Normalized());
    Near(new Vector3d(0, 0, -1), root.Hit);
    Near(new Vector3d(0, 0, -1), root.Normal);

    RayNode shadow = Assert.Single(root.Children, c => c.Kind == RayKind.Shadow);
    Assert.False(shadow.Blocked);
    Near(root.Hit!.Value, shadow.Origin);
    Near(new Vector3d(-5, 5, -5) - root.Hit.Value, shadow.Direction);
    return root;
  }

  [Fact]
  public void Centre_of_mirror_sphere_has_primary_shadow_and_reflected_rays()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd);
    ProbeResult probe = PixelProbe.Probe(job, 50, 50);

    RayNode root = CentreHitWithItsShadowRay(probe);

    RayNode reflected = Assert.Single(root.Children, c => c.Kind == RayKind.Reflected);
    Assert.Equal(1, reflected.Depth);
    Near(root.Hit.Value, reflected.Origin);
    Near(-Vector3d.UnitZ, reflected.Direction);
    // Straight back past the camera, parallel to the floor: background, or (the real Plane, like GrCis's,
    // only refuses exactly parallel rays) the floor seen edge-on at an astronomical distance.
    Assert.True(reflected.Hit == null || reflected.Hit.Value.Length > 1e9, $"reflected ray hit {reflected.Hit}");
    Assert.DoesNotContain(probe.AllRays, r => r.Kind == RayKind.Refracted);
  }

  [Fact]
  public void Probe_colour_and_hash_match_the_render()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd with { SamplesPerPixel = 1 });
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    ProbeResult probe = PixelProbe.Probe(job, 30, 60);
    // Recomputed in double precision; the framebuffer stores floats.
    for (int b = 0; b < 3; b++)
      Assert.Equal(image.GetPixel(30, 60)[b], probe.PixelColor[b], 1e-6);
    // One centred sample per pixel: the probed sample is the pixel.
    Assert.Equal(probe.PixelColor, probe.SampleColor);
    Assert.Equal(image.GetPixel(30, 60), PixelProbe.Probe(job, 30, 60, image).PixelColor);
    Assert.NotEqual(0L, probe.Hash);
    Assert.Contains("Primary", probe.ToString());
  }

  [Fact]
  public void Mirror_reflection_below_the_centre_hits_the_floor_along_the_mirrored_direction()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd);
    bool found = false;
    for (int y = 51; y < 101 && !found; y++)
    {
      RayNode root = PixelProbe.Probe(job, 50, y).Rays!;
      if (root.Hit == null || root.Solid is not Sphere)
        break;
      RayNode reflected = root.Children.Single(c => c.Kind == RayKind.Reflected);
      Vector3d n = root.Normal!.Value, d = root.Direction;
      Near(d - 2 * Vector3d.Dot(d, n) * n, reflected.Direction, 1e-9);
      if (reflected.Hit is Vector3d floor)
      {
        Assert.Equal(-1.0, floor.Y, 9);
        Assert.IsType<Plane>(reflected.Solid);
        Assert.Contains(reflected.Children, c => c.Kind == RayKind.Shadow);
        found = true;
      }
    }
    Assert.True(found, "no pixel below the centre reflects the floor");
  }

  [Fact]
  public void Glass_sphere_refracts_through_its_far_side()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Odd);
    ProbeResult probe = PixelProbe.Probe(job, 50, 50);
    RayNode into = probe.Rays!.Children.Single(c => c.Kind == RayKind.Refracted);
    Near(Vector3d.UnitZ, into.Direction.Normalized());
    Near(new Vector3d(0, 0, 1), into.Hit); // exits through the back of the unit sphere
    RayNode outOf = into.Children.First(c => c.Kind == RayKind.Refracted);
    Assert.Equal(2, outOf.Depth);
    Assert.Contains(probe.Rays!.Children, c => c.Kind == RayKind.Reflected);
  }

  [Fact]
  public void Probe_outside_the_image_is_refused()
  {
    RenderJob job = RenderJob.Create(TestScenes.PlaneAt(5), Odd);
    Assert.Throws<ArgumentOutOfRangeException>(() => PixelProbe.Probe(job, 101, 0));
  }

  /// <summary>The path a probe shows: bounce after bounce, each starting where the one before hit.</summary>
  static System.Collections.Generic.List<RayNode> Chain(RayNode root)
  {
    var chain = new System.Collections.Generic.List<RayNode> { root };
    while (chain[^1].Children.SingleOrDefault(c => c.Kind != RayKind.Shadow) is RayNode next)
      chain.Add(next);
    return chain;
  }

  [Theory]
  [InlineData(SamplerKind.CorrelatedMultiJitter)]
  [InlineData(SamplerKind.Sobol)]
  public void Path_traced_probe_colour_matches_the_render_with_each_sampler(SamplerKind sampler)
  {
    // The probe's worker is built as the render's workers are: same sampler, seed and frame, so the same pixel.
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(),
      Odd with { Width = 21, Height = 21, SamplesPerPixel = 4, Algorithm = RenderAlgorithm.Path, Seed = 3, Sampler = sampler });
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    foreach ((int x, int y) in new[] { (10, 10), (4, 15) })
    {
      ProbeResult probe = PixelProbe.Probe(job, x, y);
      for (int b = 0; b < 3; b++)
        Assert.Equal(image.GetPixel(x, y)[b], probe.PixelColor[b], 1e-6);
    }
  }

  [Fact]
  public void Path_tracing_probe_shows_the_path_as_a_chain_of_bounces_with_their_shadow_rays()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd with { Algorithm = RenderAlgorithm.Path });
    ProbeResult probe = PixelProbe.Probe(job, 50, 50);

    // The point light is sampled from the hit (next-event estimation), as Whitted shades it.
    RayNode root = CentreHitWithItsShadowRay(probe);

    var chain = Chain(root);
    Assert.True(chain.Count >= 2, "the path has no bounce");
    for (int k = 1; k < chain.Count; k++)
    {
      RayNode before = chain[k - 1], ray = chain[k];
      Assert.Equal(RayKind.Reflected, ray.Kind);
      Assert.Equal(before.Depth + 1, ray.Depth);
      Near(before.Hit!.Value, ray.Origin);
      // Reflected: back to the side the ray came from.
      Assert.True(Vector3d.Dot(ray.Direction, before.Normal!.Value) * Vector3d.Dot(before.Direction, before.Normal.Value) < 0.0);
    }
  }

  [Fact]
  public void Path_tracing_probe_tells_refracted_bounces_from_reflected_ones()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(glass: true), Odd with { Algorithm = RenderAlgorithm.Path });
    int refracted = 0;
    for (int x = 44; x <= 56; x++)
    {
      var chain = Chain(PixelProbe.Probe(job, x, 50).Rays!);
      for (int k = 1; k < chain.Count; k++)
      {
        RayNode before = chain[k - 1], ray = chain[k];
        double side = Vector3d.Dot(ray.Direction, before.Normal!.Value) * Vector3d.Dot(before.Direction, before.Normal.Value);
        // Refracted: on through the surface; reflected: back.
        Assert.Equal(ray.Kind == RayKind.Refracted, side > 0.0);
        if (ray.Kind == RayKind.Refracted)
          refracted++;
      }
    }
    Assert.True(refracted > 0, "no refracted bounce in 13 glass-sphere paths");
  }
}
