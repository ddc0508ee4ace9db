using System;
using System.Linq;
using Rendering;
using Rendering.Distributed;
using Rendering.Accel;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.ImageFunctions;

public class DistributedRayTracingTests
{
  static FloatImage Render(IRayScene sc, RayCasting f, int spp, int threads = 2, long seed = 0) =>
    PathTracingTests.Render(sc, f, 32, spp, threads, seed);

  [Fact]
  public void Without_glossy_rays_it_renders_exactly_what_Whitted_ray_tracing_renders()
  {
    var d = new DistributedRayTracing { GlossyReflections = false, GlossyRefractions = false };
    Assert.Equal(Render(Scenes.Create("Two spheres"), new RayTracing(), 4).Data, Render(Scenes.Create("Two spheres"), d, 4).Data);
  }

  [Fact]
  public void Glossy_rays_blur_reflections_without_changing_the_mean_brightness_much()
  {
    FloatImage whitted = Render(Scenes.Create("Test scene"), new RayTracing(), 16);
    FloatImage glossy = Render(Scenes.Create("Test scene"), new DistributedRayTracing(), 16);
    Assert.NotEqual(whitted.Data, glossy.Data);
    double mw = whitted.Data.Average(v => (double)v), mg = glossy.Data.Average(v => (double)v);
    // The normalised lobe moves light around; only the part below the surface is lost.
    Assert.InRange(mg / mw, 0.85, 1.02);
    // Blurring makes neighbouring pixels of the checkered floor's reflection more alike: less total variation.
    Assert.True(Variation(glossy) < Variation(whitted), $"{Variation(glossy)} vs {Variation(whitted)}");
  }

  static double Variation(FloatImage image)
  {
    double sum = 0.0;
    for (int y = 0; y < image.Height; y++)
      for (int x = 1; x < image.Width; x++)
        sum += Math.Abs(image.Data[(y * image.Width + x) * 3 + 1] - image.Data[(y * image.Width + x - 1) * 3 + 1]);
    return sum;
  }

  [Fact]
  public void Same_seed_gives_the_same_image_on_any_number_of_threads()
  {
    FloatImage one = Render(Scenes.Create("Test scene"), new DistributedRayTracing(), 9, threads: 1);
    FloatImage two = Render(Scenes.Create("Test scene"), new DistributedRayTracing(), 9, threads: 2);
    Assert.Equal(one.Data, two.Data);
    Assert.NotEqual(one.Data, Render(Scenes.Create("Test scene"), new DistributedRayTracing(), 9, seed: 4).Data);
  }

  [Fact]
  public void Settings_copy_to_another_instance()
  {
    var source = new DistributedRayTracing { GlossyReflections = false, GlossyRefractions = false, IdealExponent = 77, MaxLevel = 3 };
    var copy = new DistributedRayTracing();
    copy.CopySettingsFrom(source);
    Assert.False(copy.GlossyReflections);
    Assert.False(copy.GlossyRefractions);
    Assert.Equal(77, copy.IdealExponent);
    Assert.Equal(3, copy.MaxLevel);
  }
}
