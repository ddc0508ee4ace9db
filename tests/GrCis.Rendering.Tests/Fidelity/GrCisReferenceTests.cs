using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Rendering.Execution;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace Rendering.Tests.Fidelity;

/// <summary>
/// Renders the classic scenes exactly as GrCis rendered its reference images (640×480, one sample
/// at the pixel centre, Whitted ray tracing with defaults, gamma 2.2, truncating quantization)
/// and compares by PSNR. On failure the render and a difference image are saved and their paths printed.
/// </summary>
public class GrCisReferenceTests
{
  const double MinPsnr = 40.0;
  const int Width = 640, Height = 480;

  readonly ITestOutputHelper output;

  public GrCisReferenceTests(ITestOutputHelper output) => this.output = output;

  /// <summary>Reference image base name → scene name in the registry.</summary>
  public static readonly IReadOnlyDictionary<string, string> ReferenceScenes = new Dictionary<string, string>
  {
    ["FiveBalls"] = "Five balls",
    ["SpherePlane"] = "Sphere on the plane",
    ["TwoSpheres"] = "Two spheres",
    ["Cylinders"] = "Cylinders",
    ["Toroids"] = "Toroids",
  };

  public static TheoryData<string> References => new(ReferenceScenes.Keys);

  [Theory]
  [MemberData(nameof(References))]
  public void Render_matches_GrCis_reference_within_40dB(string reference)
  {
    string refPath = Path.Combine(RefsDirectory(), $"{reference}_{Width}x{Height}_ss1.png");
    Assert.True(File.Exists(refPath), $"Reference image missing: {refPath}");
    Rgb8Image expected = PngFile.Load(refPath);
    Assert.Equal((Width, Height), (expected.Width, expected.Height));

    Rgb8Image actual = RenderLikeGrCis(ReferenceScenes[reference], Width, Height);
    double psnr = ImageComparison.Psnr(actual, expected);
    output.WriteLine($"{reference}: PSNR {psnr:F2} dB, max channel difference {ImageComparison.MaxChannelDifference(actual, expected)}");

    bool keep = !string.IsNullOrEmpty(Environment.GetEnvironmentVariable("GRCIS_KEEP_RENDERS"));
    if (psnr < MinPsnr || keep)
    {
      string dir = FailureDirectory();
      string renderPath = Path.Combine(dir, $"{reference}_render.png");
      string diffPath = Path.Combine(dir, $"{reference}_diff.png");
      PngFile.Save(renderPath, actual);
      ImageComparison.SaveDifference(diffPath, actual, expected);
      output.WriteLine($"Saved render to {renderPath} and difference to {diffPath}");
      if (psnr < MinPsnr)
        Assert.Fail($"{reference}: PSNR {psnr:F2} dB < {MinPsnr} dB. Render: {renderPath}; difference: {diffPath}");
    }
  }

  [Fact]
  public void Every_reference_image_has_a_scene()
  {
    string[] files = Directory.GetFiles(RefsDirectory(), "*_640x480_ss1.png");
    Assert.NotEmpty(files);
    foreach (string f in files)
    {
      string name = Path.GetFileName(f)[..^"_640x480_ss1.png".Length];
      Assert.True(ReferenceScenes.ContainsKey(name), $"Reference {f} has no fidelity test.");
      Assert.Equal(ReferenceScenes[name], Scenes.CanonicalName(name));
    }
  }

  /// <summary>GrCis's default pipeline: RayTracing defaults, SimpleImageSynthesizer, gamma 2.2, byte = (int)(c·255).</summary>
  internal static Rgb8Image RenderLikeGrCis(string sceneName, int width, int height)
  {
    IRayScene scene = Scenes.Create(sceneName);
    var renderer = new SimpleImageSynthesizer { Width = width, Height = height, Gamma = 2.2 };
    FloatImage linear = TileRenderer.Render(scene, new RayTracing(scene), renderer, new RenderOptions());
    return DisplayEncoding.ForRender(renderer.Gamma).Encode(linear);
  }

  /// <summary>The reference renders in the shared folder.</summary>
  internal static string RefsDirectory() => GrCis.Rendering.Tests.SharedFolder.Combine("refs", "grcis");

  static string FailureDirectory()
  {
    string dir = Path.Combine(AppContext.BaseDirectory, "fidelity-failures");
    Directory.CreateDirectory(dir);
    return dir;
  }
}
