using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Observation;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class BuiltInScenesTests
{
  [Fact]
  public void Catalog_lists_the_classic_scenes_in_grcis_order_with_parameter_help()
  {
    SceneCatalog catalog = SceneCatalog.WithBuiltInScenes();

    Assert.Equal(Scenes.Names, catalog.Entries.Select(e => e.Name));
    Assert.All(catalog.Entries, e => Assert.Equal(SceneEntryKind.BuiltIn, e.Kind));
    Assert.Contains("n=", catalog.Find("Two spheres")!.Tooltip);
    Assert.Contains("mat=mirror|glass", catalog.Find("Sphere flake")!.Tooltip);
    Assert.Equal(0, BuiltInScenes.AddTo(catalog)); // not listed twice
    Assert.Equal(Scenes.Names.Count, catalog.Entries.Count);
  }

  [Fact]
  public void Command_line_selects_the_default_scene_or_the_first_script_and_honours_nodefault()
  {
    using var tmp = new TempDir();
    File.WriteAllText(tmp.File("One.cs"), TestScripts.Background(0.1));
    var problems = new List<string>();

    using DemoController plain = DemoController.FromCommandLine(Array.Empty<string>(), null, problems);
    Assert.Equal(Scenes.DefaultSceneName, plain.Selected!.Name);
    Assert.Equal(Scenes.Names.Count, plain.Catalog.Entries.Count);

    using DemoController withScript = DemoController.FromCommandLine(new[] { "-scene", tmp.File("One.cs") }, null, problems);
    Assert.Equal("One", withScript.Selected!.Name);
    Assert.Equal(Scenes.Names.Count + 1, withScript.Catalog.Entries.Count);

    using DemoController bare = DemoController.FromCommandLine(new[] { "-nodefault", "-dir", tmp.Path }, null, problems);
    Assert.Equal(new[] { "One" }, bare.Catalog.Entries.Select(e => e.Name));
    Assert.Equal("One", bare.Selected!.Name);
    Assert.Empty(problems);

    using DemoController broken = DemoController.FromCommandLine(new[] { "-dir", tmp.File("nowhere"), "-bogus" }, null, problems);
    Assert.Equal(2, problems.Count);
    Assert.Contains(problems, p => p.Contains("nowhere"));
    Assert.Equal(Scenes.DefaultSceneName, broken.Selected!.Name); // the rest still loads
  }

  [Fact]
  public async Task Parameter_text_reaches_the_built_in_scene()
  {
    SceneCatalog catalog = SceneCatalog.WithBuiltInScenes();
    using var demo = new DemoController(catalog) { Settings = new RenderSettings { Width = 40, Height = 30 }, Selected = catalog.Find("Two spheres") };

    RenderResult glass = (await demo.RenderAsync())!;
    demo.Selected!.ParameterText = "n=1.0"; // no refraction: the glass sphere turns see-through
    RenderResult air = (await demo.RenderAsync())!;

    Assert.True(glass.Succeeded && air.Succeeded);
    Assert.NotEqual(glass.Image.Data, air.Image.Data);
  }

  [Fact]
  public async Task Final_image_equals_grcis_render_of_the_same_scene_and_settings()
  {
    using var tmp = new TempDir();
    string[] args = { "--size", "96x64", "--spp", "4", "--seed", "7", "--threads", "3", "-q" };
    var output = new StringWriter();
    var error = new StringWriter();
    var env = new GrCis.Cli.CliEnvironment(output, error) { WorkingDirectory = tmp.Path };
    Assert.Equal(0, GrCis.Cli.Program.Run(new[] { "render", "Two spheres", "-o", "cli.pfm" }.Concat(args).ToArray(), env));
    Assert.Equal(0, GrCis.Cli.Program.Run(new[] { "render", "Two spheres", "-o", "cli.png" }.Concat(args).ToArray(), env));

    SceneCatalog catalog = SceneCatalog.WithBuiltInScenes();
    var settings = new RenderSettings { Width = 96, Height = 64, SamplesPerPixel = 4, Seed = 7, Threads = 3, TileSize = 16 };
    using var demo = new DemoController(catalog) { Settings = settings, Selected = catalog.Find("Two spheres") };
    RenderResult result = (await demo.RenderAsync())!;
    Assert.True(result.Succeeded);

    // The tile size and the demo's coarse pass change nothing: bit for bit the CLI's linear image.
    FloatImage cli = ReadPfm(tmp.File("cli.pfm"));
    Assert.Equal((96, 64), (cli.Width, cli.Height));
    Assert.Equal(cli.Data, result.Image.Data);

    Assert.True(demo.SaveImage(tmp.File("demo.png")));
    Assert.True(PngFile.Load(tmp.File("demo.png")).ContentEquals(PngFile.Load(tmp.File("cli.png"))));
  }

  [Fact]
  public void Probe_of_the_default_scene_shows_the_reflection_of_the_orange_sphere()
  {
    // Sphere on the plane: unit sphere at the origin (Ks 0.4, so mirrored rays are traced), floor y = −1,
    // camera at (0.7, 0.5, −5), one point light at (−5, 3, −3).
    SceneCatalog catalog = SceneCatalog.WithBuiltInScenes();
    var settings = new RenderSettings { Width = 80, Height = 60, Threads = 2 };
    RenderJob job = catalog.Build(catalog.Find("Sphere on the plane")!, "", settings).ToJob();

    ProbeResult centre = PixelProbe.Probe(job, 40, 30);
    RayNode primary = centre.Rays!;
    Assert.Equal(RayKind.Primary, primary.Kind);
    Near(new Vector3d(0.7, 0.5, -5.0), primary.Origin);
    Assert.IsType<Sphere>(primary.Solid);
    Vector3d hit = primary.Hit!.Value;
    Assert.Equal(1.0, hit.Length, 9);               // on the unit sphere
    Near(hit, primary.Normal!.Value.Normalized(), 1e-9); // whose normal is the position

    // The centre faces away from the light (no shadow ray); its mirrored ray goes down to the floor.
    Assert.DoesNotContain(primary.Children, c => c.Kind == RayKind.Shadow);
    RayNode mirrored = Assert.Single(primary.Children, c => c.Kind == RayKind.Reflected);
    Vector3d d = primary.Direction.Normalized(), n = hit;
    Near(d - 2.0 * Vector3d.Dot(d, n) * n, mirrored.Direction.Normalized(), 1e-9);
    Assert.IsType<Plane>(mirrored.Solid);
    Assert.Equal(-1.0, mirrored.Hit!.Value.Y, 6); // the floor, y = −1 (world point through a rotated plane: ~1e-8)
    Assert.DoesNotContain(centre.AllRays, r => r.Kind == RayKind.Refracted);

    // Up and left, towards the light, the sphere is lit: one unblocked shadow ray aimed at the light.
    RayNode? lit = null;
    for (int k = 1; k < 30 && lit == null; k++)
    {
      RayNode p = PixelProbe.Probe(job, 40 - k, 30 - k).Rays!;
      if (p.Solid is Sphere && p.Children.Any(c => c.Kind == RayKind.Shadow))
        lit = p;
    }
    Assert.NotNull(lit);
    RayNode shadow = Assert.Single(lit!.Children, c => c.Kind == RayKind.Shadow);
    Assert.False(shadow.Blocked);
    Near(new Vector3d(-5.0, 3.0, -3.0) - lit.Hit!.Value, shadow.Direction, 1e-9);
    Assert.True(Vector3d.Dot(lit.Normal!.Value, shadow.Direction) > 0.0);

    // The probe recomputes exactly what the render shows there.
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    for (int b = 0; b < 3; b++)
      Assert.Equal(image.GetPixel(40, 30)[b], centre.PixelColor[b], 1e-6);
  }

  [Fact]
  public void Depth_map_of_the_default_scene_is_the_distance_to_the_sphere()
  {
    SceneCatalog catalog = SceneCatalog.WithBuiltInScenes();
    var settings = new RenderSettings { Width = 80, Height = 60, Threads = 2 };
    RenderJob job = catalog.Build(catalog.Find("Sphere on the plane")!, "", settings).ToJob();
    ExtraViews views = ExtraViews.Compute(job);

    RayNode primary = PixelProbe.Probe(job, 40, 30).Rays!;
    // Nearest root of |o + t·d| = 1 for the pixel's ray, solved here independently of the renderer.
    Vector3d o = primary.Origin, dir = primary.Direction.Normalized();
    double b = Vector3d.Dot(o, dir), c = o.LengthSquared - 1.0;
    double t = -b - Math.Sqrt(b * b - c);
    Assert.Equal(t, views.DepthAt(40, 30), 9);
    Assert.True(views.DepthAt(40, 59) > 0 && views.DepthAt(40, 59) < double.PositiveInfinity); // floor
    Assert.True(double.IsPositiveInfinity(views.DepthAt(40, 0)));                               // sky
  }

  static void Near(Vector3d expected, Vector3d actual, double tol = 1e-12) =>
    Assert.True((expected - actual).Length < tol, $"expected {expected}, got {actual}");

  /// <summary>Reads the little-endian 3-band PFM the CLI writes (rows bottom to top).</summary>
  static FloatImage ReadPfm(string path)
  {
    byte[] bytes = File.ReadAllBytes(path);
    int pos = 0;
    string Line()
    {
      int start = pos;
      while (bytes[pos] != (byte)'\n')
        pos++;
      return System.Text.Encoding.ASCII.GetString(bytes, start, pos++ - start);
    }
    Assert.Equal("PF", Line());
    int[] size = Line().Split(' ').Select(int.Parse).ToArray();
    Assert.Equal("-1.0", Line());
    var image = new FloatImage(size[0], size[1]);
    int row = size[0] * 3;
    for (int y = size[1] - 1; y >= 0; y--)
      for (int i = 0; i < row; i++, pos += 4)
        image.Data[y * row + i] = BitConverter.ToSingle(bytes, pos);
    return image;
  }
}
