using System.IO;
using System.Linq;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace GrCis.Scripting.Tests;

/// <summary>
/// Solids written in a scene script or a module that fill only the local normal or only the local tangents (GrCis's
/// completion contract since 2020) render like the library's Sphere, through either access path.
/// </summary>
public class CompletionContractScriptTests(ITestOutputHelper output)
{
  static string Contract(string name) => Path.Combine(TestData.Root, "contract", name);

  static Rgb8Image Render(ScriptScene r, AccelMode mode)
  {
    var tracing = new RayTracing(r.Scene) { Accel = mode };
    var renderer = new SimpleImageSynthesizer { Width = 160, Height = 120 };
    return Rgb8Image.FromFloatImage(TileRenderer.Render(r.Scene, tracing, renderer, new RenderOptions { Threads = 2, Seed = 7 }));
  }

  void AssertLooksLikeSphere(Rgb8Image actual, Rgb8Image sphere, string what)
  {
    double psnr = ImageComparison.Psnr(actual, sphere);
    output.WriteLine($"{what}: PSNR {psnr:F2} dB against Sphere");
    if (psnr >= 40.0)
      return;
    string diff = Path.Combine(Path.GetTempPath(), $"grcis-contract-{what.Replace(' ', '-')}-diff.png");
    ImageComparison.SaveDifference(diff, actual, sphere);
    Assert.Fail($"{what}: PSNR {psnr:F2} dB < 40 dB; difference: {diff}");
  }

  [Theory]
  [InlineData(AccelMode.None)]
  [InlineData(AccelMode.Bvh)]
  public void A_script_class_filling_only_NormalLocal_renders_like_Sphere(AccelMode mode)
  {
    using var host = new ScriptHost();
    CompiledScript script = host.Compile(Contract("StudentSphereScene.cs"));
    Rgb8Image sphere = Render(host.Run(script, "solid=library"), mode);
    Rgb8Image student = Render(host.Run(script, "solid=student"), mode);

    Assert.Equal("MySphere", ((CSGInnerNode)host.Run(script, "solid=student").Scene.Intersectable!).Children.First().GetType().Name);
    AssertLooksLikeSphere(student, sphere, $"script NormalLocal {mode}");
  }

  [Theory]
  [InlineData(AccelMode.None)]
  [InlineData(AccelMode.Bvh)]
  public void A_module_class_filling_only_the_tangents_renders_like_Sphere(AccelMode mode)
  {
    using var host = new ScriptHost();
    host.AddModule(Contract(Path.Combine("modules", "Globes")));
    Rgb8Image sphere = Render(host.Load(Contract("StudentSphereScene.cs"), "solid=library"), mode);
    Rgb8Image globe = Render(host.Load(Contract("ModuleGlobeScene.cs")), mode);
    AssertLooksLikeSphere(globe, sphere, $"module tangents {mode}");
  }

  [Fact]
  public void Both_access_paths_complete_a_script_solid_alike()
  {
    using var host = new ScriptHost();
    ScriptScene r = host.Load(Contract("StudentSphereScene.cs"), "solid=student");
    Rgb8Image none = Render(r, AccelMode.None);
    Rgb8Image bvh = Render(r, AccelMode.Bvh);
    Assert.True(none.ContentEquals(bvh), $"max channel difference {ImageComparison.MaxChannelDifference(none, bvh)}");
  }
}
