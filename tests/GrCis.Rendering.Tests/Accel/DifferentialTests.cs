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
