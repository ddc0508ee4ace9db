using System;
using System.IO;
using System.Linq;
using OpenTK.Mathematics;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public sealed class ExtraViewsTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-views-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  static readonly RenderSettings Odd = new() { Width = 33, Height = 33, Threads = 2 };

  [Fact]
  public void Plane_at_z5_seen_from_the_origin_has_depth_5_at_the_centre()
  {
    RenderJob job = RenderJob.Create(TestScenes.PlaneAt(5), Odd);
    ExtraViews views = ExtraViews.Compute(job);

    Assert.Equal(5.0, views.DepthAt(16, 16), 12);
    Assert.Equal(5.0, views.ValueAt(MapKind.Depth, 16, 16), 12);
    Assert.True((views.NormalAt(16, 16) - new Vector3d(0, 0, -1)).Length < 1e-12);
    Assert.Equal(0.0, views.ValueAt(MapKind.NormalRelative, 16, 16), 6);
    // Off centre the distance grows as 5 / cos of the ray angle.
    RayNode corner = PixelProbe.Probe(job, 0, 0).Rays!;
    Assert.Equal(5.0 / corner.Direction.Normalized().Z, views.DepthAt(0, 0), 9);
    Assert.Contains("depth 5", views.Describe(MapKind.Depth, 16, 16));
  }

  [Fact]
  public void Ray_counts_agree_with_the_probe_and_with_the_samples()
  {
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd);
    ExtraViews views = ExtraViews.Compute(job);
    foreach ((int x, int y) in new[] { (16, 16), (3, 30), (0, 0), (20, 25) })
    {
      Assert.Equal(1.0, views.ValueAt(MapKind.PrimaryRays, x, y));
      int probed = PixelProbe.Probe(job, x, y).AllRays.Count();
      Assert.Equal(probed, views.ValueAt(MapKind.AllRays, x, y));
    }
    Assert.True(views.AllRaysKnown);

    ExtraViews ss = ExtraViews.Compute(RenderJob.Create(TestScenes.SphereOnPlane(), Odd with { SamplesPerPixel = 9 }));
    Assert.Equal(9.0, ss.ValueAt(MapKind.PrimaryRays, 7, 7));
    Assert.True(ss.ValueAt(MapKind.AllRays, 16, 16) > 9.0);
  }

  [Fact]
  public void Path_tracing_fills_the_views_like_ray_tracing_and_counts_its_rays()
  {
    ExtraViews whitted = ExtraViews.Compute(RenderJob.Create(TestScenes.SphereOnPlane(), Odd));
    RenderJob job = RenderJob.Create(TestScenes.SphereOnPlane(), Odd with { Algorithm = RenderAlgorithm.Path });
    ExtraViews path = ExtraViews.Compute(job);
    foreach ((int x, int y) in new[] { (16, 16), (3, 30), (20, 25) })
    {
      // The camera rays are the same: same first hits.
      Assert.Equal(whitted.DepthAt(x, y), path.DepthAt(x, y));
      Assert.Equal(whitted.NormalAt(x, y), path.NormalAt(x, y));
      Assert.Equal(1.0, path.ValueAt(MapKind.PrimaryRays, x, y));
      Assert.Equal(PixelProbe.Probe(job, x, y).AllRays.Count(), path.ValueAt(MapKind.AllRays, x, y));
    }
    Assert.True(path.ValueAt(MapKind.AllRays, 16, 16) >= 3.0);   // camera ray, shadow ray, a bounce at least
  }

  [Fact]
  public void Background_pixels_have_infinite_depth_and_no_normal()
  {
    ExtraViews views = ExtraViews.Compute(RenderJob.Create(TestScenes.SphereOnPlane(), Odd));
    Assert.True(double.IsPositiveInfinity(views.DepthAt(16, 0)));
    Assert.Equal(Vector3d.Zero, views.NormalAt(16, 0));
    Assert.Null(views.HitPointAt(16, 0));
  }

  [Fact]
  public void Maps_export_as_png_csv_and_ply()
  {
    RenderJob job = RenderJob.Create(TestScenes.PlaneAt(5), Odd);
    ExtraViews views = ExtraViews.Compute(job);

    foreach (MapKind kind in Enum.GetValues<MapKind>())
    {
      string png = Path.Combine(dir, $"{kind}.png");
      views.SavePng(kind, png);
      Rgb8Image img = PngFile.Load(png);
      Assert.Equal((33, 33), (img.Width, img.Height));
      string csv = Path.Combine(dir, $"{kind}.csv");
      views.SaveCsv(kind, csv);
      Assert.Equal(1 + 33 * 33, File.ReadAllLines(csv).Length);
    }
    Assert.Contains("16,16,5", File.ReadAllLines(Path.Combine(dir, "Depth.csv")));
    Assert.Contains("16,16,0,0,-1", File.ReadAllLines(Path.Combine(dir, "NormalAbsolute.csv")));

    string ply = Path.Combine(dir, "cloud.ply");
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    views.SavePointCloud(ply, image);
    string[] lines = File.ReadAllLines(ply);
    Assert.Equal("ply", lines[0]);
    Assert.Contains("element vertex 1089", lines);
    int body = Array.IndexOf(lines, "end_header") + 1;
    Assert.Equal(1089, lines.Length - body);
    Assert.All(lines.Skip(body), l => Assert.Equal("5", l.Split(' ')[2]));
    Assert.Equal(9, lines[body].Split(' ').Length);
    Assert.Empty(Directory.GetFiles(dir, "*.tmp-*"));
  }

  [Fact]
  public async System.Threading.Tasks.Task Noise_view_is_the_renders_own_standard_error_and_says_when_there_is_none()
  {
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Glass ball", _ => TestScenes.SphereOnPlane(glass: true));
    using var demo = new DemoController(catalog) { Settings = Odd with { SamplesPerPixel = 16 }, Algorithm = RenderAlgorithm.Path, Selected = catalog.Entries[0] };
    RenderResult? result = await demo.RenderAsync();
    Assert.NotNull(result?.Frame.Noise);
    ExtraViews views = demo.ComputeExtraViews();

    float[] variance = result!.Frame.Noise!.Variance.Data;
    for (int y = 0; y < Odd.Height; y += 4)
      for (int x = 0; x < Odd.Width; x += 4)
        Assert.Equal(Math.Sqrt(variance[y * Odd.Width + x]), views.ValueAt(MapKind.Noise, x, y), 12);
    Assert.True(views.Range(MapKind.Noise).Max > 0.0);
    Assert.Contains("noise ±", views.Describe(MapKind.Noise, 16, 16));
    string csv = Path.Combine(dir, "noise.csv");
    views.SaveCsv(MapKind.Noise, csv);
    Assert.Equal("x,y,standard_error", File.ReadLines(csv).First());

    // One sample per pixel: no estimate, and the read-out says why.
    demo.Settings = Odd;
    await demo.RenderAsync();
    ExtraViews single = demo.ComputeExtraViews();
    Assert.True(double.IsNaN(single.ValueAt(MapKind.Noise, 16, 16)));
    Assert.Contains("no noise estimate", single.Describe(MapKind.Noise, 16, 16));
    Assert.Equal(0.0, single.ToImage(MapKind.Noise).Data.Max());
  }
}
