using System;
using System.Linq;
using GrCis.Testing;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using Xunit.Abstractions;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// Every test scene rendered through the faithful path and the prepared fast path must give the
/// same image, bit for bit: the fast path transforms rays through the same matrices in the same order
/// and completes hits with the same matrices, so no floating-point order differs.
/// </summary>
public class DifferentialTests
{
  readonly ITestOutputHelper output;

  public DifferentialTests(ITestOutputHelper output) => this.output = output;

  public static TheoryData<string> SceneNames()
  {
    var data = new TheoryData<string>();
    foreach ((string name, _) in TestScenes.All)
      data.Add(name);
    return data;
  }

  static IRayScene Build(string name) => TestScenes.All.First(s => s.Name == name).Build();

  [Theory]
  [MemberData(nameof(SceneNames))]
  public void Fast_path_renders_the_same_image_as_the_faithful_path(string name)
  {
    FloatImage slow = RenderHelper.Render(Build(name), AccelMode.None, 96, 72);
    FloatImage fast = RenderHelper.Render(Build(name), AccelMode.Bvh, 96, 72);
    AssertIdentical(name, slow, fast);
  }

  [Theory]
  [InlineData("five-balls")]
  [InlineData("csg-mix")]
  public void Ray_casting_fast_path_renders_the_same_image(string name)
  {
    FloatImage slow = RenderHelper.Render(Build(name), AccelMode.None, 80, 60, rayCasting: true);
    FloatImage fast = RenderHelper.Render(Build(name), AccelMode.Bvh, 80, 60, rayCasting: true);
    AssertIdentical(name, slow, fast);
  }

  [Fact]
  public void Fast_path_with_supersampling_and_threads_matches_faithful_single_thread()
  {
    FloatImage slow = RenderHelper.Render(TestScenes.TwoSpheresGlass(), AccelMode.None, 48, 36, spp: 4, threads: 1);
    FloatImage fast = RenderHelper.Render(TestScenes.TwoSpheresGlass(), AccelMode.Bvh, 48, 36, spp: 4, threads: 3);
    AssertIdentical("two-spheres 4 spp", slow, fast);
  }

  void AssertIdentical(string name, FloatImage expected, FloatImage actual)
  {
    int differing = 0;
    double maxDiff = 0.0;
    for (int k = 0; k < expected.Data.Length; k++)
    {
      double d = System.Math.Abs(expected.Data[k] - actual.Data[k]);
      if (d != 0.0 || float.IsNaN(expected.Data[k]) != float.IsNaN(actual.Data[k]))
      {
        differing++;
        maxDiff = System.Math.Max(maxDiff, d);
      }
    }
    output.WriteLine($"{name}: {differing} differing channels, max difference {maxDiff}");
    Assert.True(differing == 0, $"{name}: {differing} channels differ (max {maxDiff}).");
  }
}

/// <summary>The eleven classic GrCis scenes through both paths (small images: the faithful path is slow).</summary>
public class ClassicDifferentialTests
{
  readonly ITestOutputHelper output;

  public ClassicDifferentialTests(ITestOutputHelper output) => this.output = output;

  public static TheoryData<string> ClassicNames()
  {
    var data = new TheoryData<string>();
    foreach (string name in global::Rendering.Scenes.Names)
      data.Add(name);
    return data;
  }

  [Theory]
  [MemberData(nameof(ClassicNames))]
  public void Classic_scene_renders_identically_on_both_paths(string name)
  {
    // Sphere flake at depth 3 keeps the faithful render short; the structure is the same.
    string? param = name == "Sphere flake" ? "depth=3" : null;
    FloatImage slow = RenderHelper.Render(global::Rendering.Scenes.Create(name, param), AccelMode.None, 64, 48);
    FloatImage fast = RenderHelper.Render(global::Rendering.Scenes.Create(name, param), AccelMode.Bvh, 64, 48);
    int differing = 0;
    for (int k = 0; k < slow.Data.Length; k++)
      if (slow.Data[k] != fast.Data[k] && !(float.IsNaN(slow.Data[k]) && float.IsNaN(fast.Data[k])))
        differing++;
    output.WriteLine($"{name}: {differing} differing channels");
    Assert.Equal(0, differing);
  }
}
