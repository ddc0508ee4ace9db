using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>Path tracing checked against analytic answers (white furnaces), Whitted's direct light, itself (convergence, MIS) and its determinism.</summary>
public class PathTracingTests
{
  internal static FloatImage Render(IRayScene sc, RayCasting f, int size, int spp, int threads = 2, long seed = 0, AccelMode accel = AccelMode.Bvh,
    RenderContext? context = null)
  {
    f.Accel = accel;
    var synth = new SupersamplingImageSynthesizer { Width = size, Height = size, Supersampling = spp };
    return TileRenderer.Render(sc, f, synth, new RenderOptions { Threads = threads, Seed = seed, TileSize = 8 }, context: context);
  }

  static double Mean(FloatImage image, int band = 1)
  {
    double sum = 0.0;
    for (int i = band; i < image.Data.Length; i += image.Bands)
      sum += image.Data[i];
    return sum / (image.Data.Length / image.Bands);
  }

  /// <summary>A closed cube [-1,1]³ of inward-facing emissive Lambertian walls (radiance le, albedo a), seen from its centre.</summary>
  static IRayScene Furnace(double a, double le)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { a, a, a }, 0.0, 1.0, 0.0, 1) { Emission = new[] { le, le, le } });
    Matrix4d[] faces =
    {
      Matrix4d.CreateTranslation(0, 0, -1),
      Matrix4d.RotateX(Math.PI) * Matrix4d.CreateTranslation(0, 0, 1),
      Matrix4d.RotateY(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-1, 0, 0),
      Matrix4d.RotateY(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(1, 0, 0),
      Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, -1, 0),
      Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, 1, 0),
    };
    foreach (Matrix4d f in faces)
      root.InsertChild(new Plane(-1, 1, -1, 1), f);
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0.1, -0.2, 0.05), new Vector3d(0.2, 0.1, 1.0), 90.0),
      Sources = new LinkedList<ILightSource>(),
    };
  }

  [Theory]
  [InlineData(true, true)]
  [InlineData(true, false)]
  [InlineData(false, false)]
  public void White_furnace_closed_emissive_box_gives_le_over_one_minus_albedo(bool nee, bool mis)
  {
    // Every path sees emission le at each bounce and keeps a fraction a: L = le (1 + a + a² + …) = le / (1 − a).
    const double a = 0.5, le = 1.0;
    var pt = new PathTracing { NextEventEstimation = nee, MultipleImportanceSampling = mis, MaxLevel = 200 };
    // Light sampling alone has a heavy tail near the cube's edges (1/r² to the next face): it needs more samples.
    FloatImage image = Render(Furnace(a, le), pt, 32, nee && !mis ? 1024 : 64);
    Assert.Equal(le / (1.0 - a), Mean(image), 2.0 * 0.01);   // within 1 %
  }

  [Fact]
  public void Convex_diffuse_sphere_in_a_uniform_environment_reflects_albedo_times_the_environment()
  {
    const double a = 0.6, env = 2.0;
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { a, a, a }, 0.0, 1.0, 0.0, 1));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    var sc = new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { env, env, env },
      Camera = new StaticCamera(new Vector3d(0, 0, -4), Vector3d.UnitZ, 40.0),
      Sources = new LinkedList<ILightSource>(),
    };
    foreach (bool sampled in new[] { false, true })
    {
      FloatImage image = Render(sc, new PathTracing { EnvironmentSampling = sampled }, 16, 4);
      // A convex surface sees only the environment: each sample is exactly a·env (with the background sampled too,
      // its cosine-weighted sample and the scattered ray share it by MIS); the corners see env itself.
      Assert.Equal(a * env, image.Data[(8 * 16 + 8) * 3 + 1], 5);
      Assert.Equal(env, image.Data[1], 12);
    }
  }

  /// <summary>One diffuse plane seen from above, no ambient, lit by <paramref name="light"/> alone: direct light only.</summary>
  static IRayScene DiffusePlane(ILightSource light)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.9, 0.5, 0.2 }, 0.0, 0.8, 0.0, 1, 0.0));
    root.InsertChild(new Plane(), Matrix4d.RotateX(-MathHelper.PiOver2));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0, 2, -3), new Vector3d(0, -0.6, 1), 60.0),
      Sources = new LinkedList<ILightSource>(new[] { light }),
    };
  }

  [Fact]
  public void Direct_light_from_a_GrCis_point_light_equals_Whitted_diffuse_shading()
  {
    // One diffuse plane, no ambient: path tracing (direct light only, nothing else to see) must agree with Phong's kd·cos·I.
    FloatImage whitted = Render(DiffusePlane(new PointLightSource(new Vector3d(1, 3, 1), 1.3)), new RayTracing(), 16, 1);
    FloatImage path = Render(DiffusePlane(new PointLightSource(new Vector3d(1, 3, 1), 1.3)), new PathTracing(), 16, 1);
    for (int i = 0; i < whitted.Data.Length; i++)
      Assert.Equal(whitted.Data[i], path.Data[i], 5);
    Assert.True(Mean(whitted) > 0.05);
  }

  /// <summary>A student's own light (GrCis's interface, none of its classes): a point light lighting only points below a height.</summary>
  sealed class StudentLight : ILightSource
  {
    public double[]? GetIntensity(Intersection intersection, out Vector3d dir)
    {
      dir = new Vector3d(-1, 3, 1) - intersection.CoordWorld;
      if (Vector3d.Dot(dir, intersection.Normal) <= 0.0 || intersection.CoordWorld.X > 0.5)
        return null;
      return new[] { 0.7, 1.1, 0.4 };
    }
  }

  [Fact]
  public void A_students_own_light_source_lights_a_path_traced_scene_as_it_lights_Whitted()
  {
    FloatImage whitted = Render(DiffusePlane(new StudentLight()), new RayTracing(), 16, 1);
    FloatImage path = Render(DiffusePlane(new StudentLight()), new PathTracing(), 16, 1);
    for (int i = 0; i < whitted.Data.Length; i++)
      Assert.Equal(whitted.Data[i], path.Data[i], 5);
    Assert.True(Mean(whitted) > 0.02);
    Assert.Contains(whitted.Data, v => v == 0.0f);   // the part the light leaves dark
  }

  /// <summary>A material with its own scattering: Lambertian of albedo <see cref="Albedo"/> in band 1 only, cosine-sampled.</summary>
  sealed class GreenLambert : IMaterial, IScatteringMaterial
  {
    public double Albedo;
    public double[] Color { get; set; } = { 1.0, 1.0, 1.0 };
    public double Kt { get; set; }
    public double n { get; set; } = 1.0;
    public object Clone() => MemberwiseClone();

    public void Eval(Intersection hit, Vector3d wo, Vector3d wi, double[] f)
    {
      Array.Clear(f);
      if (Vector3d.Dot(wi, hit.Normal) * Vector3d.Dot(wo, hit.Normal) > 0.0)
        f[1] = Albedo / Math.PI;
    }

    public double Pdf(Intersection hit, Vector3d wo, Vector3d wi)
    {
      Vector3d nf = Vector3d.Dot(wo, hit.Normal) > 0.0 ? hit.Normal : -hit.Normal;
      return Math.Max(0.0, Vector3d.Dot(wi, nf)) / Math.PI;
    }

    public bool Sample(Intersection hit, Vector3d wo, double choice, double u, double v, out Vector3d wi, double[] weight, out double pdf, out bool delta)
    {
      Vector3d nf = Vector3d.Dot(wo, hit.Normal) > 0.0 ? hit.Normal : -hit.Normal;
      wi = SampleWarp.CosineHemisphere(u, v, nf);
      pdf = Pdf(hit, wo, wi);
      delta = false;
      Array.Clear(weight);
      weight[1] = Albedo;
      return pdf > 0.0;
    }
  }

  [Fact]
  public void A_material_with_its_own_scattering_is_used_instead_of_its_Phong_parameters()
  {
    const double a = 0.3, env = 2.0;
    var material = new GreenLambert { Albedo = a };
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, material);
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    var sc = new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { env, env, env },
      Camera = new StaticCamera(new Vector3d(0, 0, -4), Vector3d.UnitZ, 40.0),
      Sources = new LinkedList<ILightSource>(),
    };
    FloatImage image = Render(sc, new PathTracing(), 16, 4, threads: 1);
    // A convex sphere sees only the environment: a·env in the band it reflects, nothing in the others (Phong's default would give (1 − Kt)·env in all).
    int centre = (8 * 16 + 8) * 3;
    Assert.Equal(a * env, image.Data[centre + 1], 5);
    Assert.Equal(0.0, image.Data[centre], 12);
    Assert.Equal(0.0, image.Data[centre + 2], 12);
  }

  [Fact]
  public void Noise_falls_as_one_over_the_square_root_of_the_samples()
  {
    IRayScene Scene() => CornellScene.Create(diffuse: true);
    FloatImage reference = Render(Scene(), new PathTracing(), 16, 1024, seed: 1000);
    var spps = new[] { 4, 16, 64 };
    double[] rmse = spps.Select(s => Rmse(Render(Scene(), new PathTracing(), 16, s), reference, 1.0)).ToArray();
    double slope = (Math.Log(rmse[2]) - Math.Log(rmse[0])) / (Math.Log(64) - Math.Log(4));
    Assert.InRange(slope, -0.75, -0.35);
    Assert.True(rmse[0] > rmse[1] && rmse[1] > rmse[2], string.Join(", ", rmse));
  }

  /// <summary>RMSE over the pixels whose reference is at most <paramref name="limit"/> (the light's own pixels left out).</summary>
  static double Rmse(FloatImage test, FloatImage reference, double limit)
  {
    double sum = 0.0;
    int count = 0;
    for (int p = 0; p < reference.Data.Length; p += 3)
    {
      if (reference.Data[p] > limit || reference.Data[p + 1] > limit || reference.Data[p + 2] > limit)
        continue;
      for (int b = 0; b < 3; b++)
      {
        double d = test.Data[p + b] - reference.Data[p + b];
        sum += d * d;
        count++;
      }
    }
    return Math.Sqrt(sum / count);
  }

  [Fact]
  public void Light_sampling_with_and_without_MIS_and_BSDF_sampling_alone_agree_on_the_Cornell_box()
  {
    // The lower half of the image: light that arrived by bounces, without the noise of pixels that see the emitter.
    const int size = 16;
    static double LowerHalf(FloatImage image)
    {
      double sum = 0.0;
      for (int i = image.Data.Length / 2; i < image.Data.Length; i++)
        sum += image.Data[i];
      return sum / (image.Data.Length / 2);
    }
    // Its standard error from the render's own noise estimate: the bands of a pixel taken as fully correlated (an upper bound).
    static double StandardError(NoiseImage noise)
    {
      double variance = 0.0;
      for (int i = noise.Variance.Data.Length / 2; i < noise.Variance.Data.Length; i++)
        variance += noise.Variance.Data[i];
      return Math.Sqrt(variance) / (noise.Variance.Data.Length / 2);
    }
    (double Mean, double Error) Lum(bool nee, bool mis, int spp = 256)
    {
      var context = new RenderContext { Noise = new NoiseImage(size, size) };
      FloatImage image = Render(CornellScene.Create(diffuse: true), new PathTracing { NextEventEstimation = nee, MultipleImportanceSampling = mis }, size, spp,
        context: context);
      return (LowerHalf(image), StandardError(context.Noise));
    }
    var both = Lum(true, true);
    var lightOnly = Lum(true, false);
    var bsdfOnly = Lum(false, false, 1024);
    // BSDF sampling alone finds the small light rarely: its error is several times the others', even at 4× the samples.
    Assert.True(bsdfOnly.Error > 2 * both.Error, $"BSDF-only error {bsdfOnly.Error} vs MIS {both.Error}");
    Assert.Equal(both.Mean, lightOnly.Mean, 4 * Math.Sqrt(both.Error * both.Error + lightOnly.Error * lightOnly.Error));
    Assert.Equal(both.Mean, bsdfOnly.Mean, 4 * Math.Sqrt(both.Error * both.Error + bsdfOnly.Error * bsdfOnly.Error));
    Assert.True(bsdfOnly.Error < 0.05 * both.Mean, $"BSDF-only error {bsdfOnly.Error} too large for a test");
  }

  [Fact]
  public void Same_seed_gives_the_same_image_on_one_or_two_threads_and_on_both_query_paths()
  {
    FloatImage one = Render(CornellScene.Create(diffuse: false), new PathTracing(), 24, 4, threads: 1);
    FloatImage two = Render(CornellScene.Create(diffuse: false), new PathTracing(), 24, 4, threads: 2);
    FloatImage lists = Render(CornellScene.Create(diffuse: false), new PathTracing(), 24, 4, threads: 2, accel: AccelMode.None);
    Assert.Equal(one.Data, two.Data);
    Assert.Equal(one.Data, lists.Data);
    FloatImage other = Render(CornellScene.Create(diffuse: false), new PathTracing(), 24, 4, seed: 9);
    Assert.NotEqual(one.Data, other.Data);
  }

  [Fact]
  public void Cornell_box_shows_the_light_at_radiance_15_red_wall_left_green_wall_right()
  {
    FloatImage image = Render(CornellScene.Create(diffuse: true), new PathTracing(), 64, 4);
    float At(int x, int y, int b) => image.Data[(y * 64 + x) * 3 + b];
    // The light spans columns ~26..38 and rows ~7..9 of 64 (the specification's 103..153 and 27..37 of 256).
    for (int b = 0; b < 3; b++)
      Assert.Equal(15.0, At(32, 8, b), 4);
    Assert.True(At(2, 32, 0) > 3 * At(2, 32, 1), "left wall must be red");
    Assert.True(At(61, 32, 1) > 2 * At(61, 32, 0), "right wall must be green");
  }
}
