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

  [Fact]
  public void Centre_of_mirror_sphere_has_primary_shadow_and_reflected_rays()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd);
    ProbeResult probe = PixelProbe.Probe(job, 50, 50);

    RayNode root = Assert.IsType<RayNode>(probe.Rays);
    Assert.Equal(RayKind.Primary, root.Kind);
    Near(new Vector3d(0, 0, -5), root.Origin);
    Near(Vector3d.UnitZ, root.Direction);
    Near(new Vector3d(0, 0, -1), root.Hit);
    Near(new Vector3d(0, 0, -1), root.Normal);

    RayNode shadow = Assert.Single(root.Children, c => c.Kind == RayKind.Shadow);
    Assert.False(shadow.Blocked);
    Near(root.Hit!.Value, shadow.Origin);
    Near(new Vector3d(-5, 5, -5) - root.Hit.Value, shadow.Direction);

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
}
