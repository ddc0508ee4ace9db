using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>
/// Emissive spheres in the path tracer: the light a sphere sends to a Lambertian floor against the analytic
/// answer by light sampling, MIS and BSDF sampling alone; a non-uniformly scaled one left to scattered rays; determinism.
/// </summary>
public class EmissiveSphereTests
{
  const int Size = 16;
  const double Albedo = 0.8, Le = 10.0;

  /// <summary>
  /// A white Lambertian floor (y = 0) under one emissive unit sphere placed by <paramref name="place"/> above the
  /// origin, seen from 45° through a 0.1° camera: every pixel sees the origin within 0.004, where the irradiance
  /// differs from the origin's by less than 1e-4 of it.
  /// </summary>
  static IRayScene Floor(Matrix4d place)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { Albedo, Albedo, Albedo }, 0.0, 1.0, 0.0, 1));
    root.InsertChild(new Plane(), Matrix4d.RotateX(-MathHelper.PiOver2));
    var light = new Sphere();
    light.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { Le, Le, Le } });
    root.InsertChild(light, place);
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0, 2, -2), new Vector3d(0, -1, 1), 0.1),
      Sources = new LinkedList<ILightSource>(),
    };
  }

  /// <summary>The image's mean, its standard error and the mean variance of a pixel, from the render's own noise estimate.</summary>
  static (double Mean, double Error, double PixelVariance) Measure(IRayScene sc, PathTracing pt, int spp)
  {
    var context = new RenderContext { Noise = new NoiseImage(Size, Size) };
    FloatImage image = PathTracingTests.Render(sc, pt, Size, spp, context: context);
    double sum = 0.0, variance = 0.0;
    foreach (float f in image.Data)
      sum += f;
    foreach (float v in context.Noise.Variance.Data)
      variance += v;
    int pixels = Size * Size;
    // Pixels are independent (each draws from its own streams), so their variances add.
    return (sum / image.Data.Length, Math.Sqrt(variance) / pixels, variance / pixels);
  }

  /// <summary>
  /// Radiance the floor at the origin (normal +y) reflects from a convex emitter of radiance Le around the zenith:
  /// a/π·Le·∫cos θ dω over the directions that <paramref name="hits"/> accepts. Each meridian φ meets that set in
  /// [0, θmax(φ)], where ∫cos θ sin θ dθ = sin²θmax/2; θmax by bisection, φ by the midpoint rule (periodic: exact fast).
  /// </summary>
  static double Reflected(Func<Vector3d, bool> hits)
  {
    const int meridians = 512;
    double sum = 0.0;
    for (int k = 0; k < meridians; k++)
    {
      double phi = 2.0 * Math.PI * (k + 0.5) / meridians;
      double lo = 0.0, hi = 0.5 * Math.PI;
      for (int step = 0; step < 60; step++)
      {
        double theta = 0.5 * (lo + hi);
        var w = new Vector3d(Math.Sin(theta) * Math.Cos(phi), Math.Cos(theta), Math.Sin(theta) * Math.Sin(phi));
        if (hits(w))
          lo = theta;
        else
          hi = theta;
      }
      double s = Math.Sin(lo);
      sum += 0.5 * s * s;
    }
    return Albedo / Math.PI * Le * sum * (2.0 * Math.PI / meridians);
  }

  /// <summary>True when the ray from the origin along <paramref name="w"/> meets the ellipsoid of semi-axes <paramref name="s"/> around <paramref name="c"/>.</summary>
  static bool HitsEllipsoid(Vector3d w, Vector3d c, Vector3d s)
  {
    Vector3d q0 = new(-c.X / s.X, -c.Y / s.Y, -c.Z / s.Z), q1 = new(w.X / s.X, w.Y / s.Y, w.Z / s.Z);
    double a = Vector3d.Dot(q1, q1), b = Vector3d.Dot(q0, q1), disc = b * b - a * (Vector3d.Dot(q0, q0) - 1.0);
    return disc >= 0.0 && -b + Math.Sqrt(disc) > 0.0;
  }

  static void AssertConverged(double expected, (double Mean, double Error, double PixelVariance) m, string what)
  {
    // The error bound first, so that 4 standard errors fit in the 2 % asked of every estimator.
    Assert.True(m.Error < 0.005 * expected, $"{what}: standard error {m.Error} too large for the test");
    Assert.True(Math.Abs(m.Mean - expected) < 4.0 * m.Error, $"{what}: {m.Mean} vs {expected} ± {m.Error}");
    Assert.Equal(expected, m.Mean, 0.02 * expected);
  }

  [Fact]
  public void Emissive_sphere_lights_a_Lambertian_floor_with_pi_Le_r2_over_d2_by_light_sampling_MIS_and_BSDF_sampling()
  {
    const double r = 0.25, d = 1.0;
    // E = π·Le·sin²θmax = π·Le·(r/d)², reflected as a/π·E.
    double expected = Albedo * Le * (r / d) * (r / d);
    Assert.Equal(expected, Reflected(w => HitsEllipsoid(w, new Vector3d(0, d, 0), new Vector3d(r, r, r))), 1e-9);

    Matrix4d place = Matrix4d.Scale(r) * Matrix4d.CreateTranslation(0, d, 0);
    var mis = Measure(Floor(place), new PathTracing(), 4096);
    var light = Measure(Floor(place), new PathTracing { MultipleImportanceSampling = false }, 4096);
    var bsdf = Measure(Floor(place), new PathTracing { NextEventEstimation = false }, 4096);
    AssertConverged(expected, mis, "NEE + MIS");
    AssertConverged(expected, light, "NEE alone");
    AssertConverged(expected, bsdf, "BSDF sampling alone");
    // Sampling the cone leaves little but the cosine's variation; scattered rays find the sphere with probability (r/d)².
    Assert.True(bsdf.PixelVariance > 5.0 * mis.PixelVariance, $"pixel variance: BSDF alone {bsdf.PixelVariance}, MIS {mis.PixelVariance}");
    Assert.True(bsdf.PixelVariance > 5.0 * light.PixelVariance, $"pixel variance: BSDF alone {bsdf.PixelVariance}, NEE alone {light.PixelVariance}");
  }

  [Fact]
  public void A_non_uniformly_scaled_emissive_sphere_is_left_to_scattered_rays_and_converges_without_bias()
  {
    Vector3d centre = new(0, 1, 0), axes = new(0.3, 0.2, 0.15);
    Matrix4d place = Matrix4d.Scale(axes) * Matrix4d.CreateTranslation(centre);
    Assert.Equal(0, EmitterSet.Of(Floor(place).Intersectable).Count);

    // No light sample for it: with next-event estimation on, every path and weight is BSDF sampling's.
    FloatImage on = PathTracingTests.Render(Floor(place), new PathTracing(), Size, 16);
    FloatImage off = PathTracingTests.Render(Floor(place), new PathTracing { NextEventEstimation = false }, Size, 16);
    Assert.Equal(off.Data, on.Data);

    double expected = Reflected(w => HitsEllipsoid(w, centre, axes));
    AssertConverged(expected, Measure(Floor(place), new PathTracing(), 4096), "ellipsoid");
  }

  [Fact]
  public void Same_seed_gives_the_same_image_with_emissive_spheres_on_one_or_two_threads_and_both_query_paths()
  {
    static IRayScene Scene()
    {
      var sc = (DefaultRayScene)Floor(Matrix4d.Scale(0.25) * Matrix4d.CreateTranslation(0.3, 0.8, 0.2));
      var root = (CSGInnerNode)sc.Intersectable!;
      // A second light under a mirrored, rotated parent, a rectangle light and a ball that casts shadows.
      var mirrored = new CSGInnerNode(SetOperation.Union);
      root.InsertChild(mirrored, Matrix4d.Scale(-1.0, 1.0, 1.0) * Matrix4d.RotateY(0.6));
      var second = new Sphere();
      second.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.0, 0.5, 0.0, 1) { Emission = new[] { 4.0, 2.0, 1.0 } });
      mirrored.InsertChild(second, Matrix4d.Scale(0.15) * Matrix4d.CreateTranslation(0.5, 0.4, -0.3));
      var quad = new Plane(-0.2, 0.2, -0.2, 0.2);
      quad.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { 3.0, 3.0, 3.0 } });
      root.InsertChild(quad, Matrix4d.RotateX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(-0.5, 1.5, 0.0));
      root.InsertChild(new Sphere(), Matrix4d.Scale(0.2) * Matrix4d.CreateTranslation(0.0, 0.2, 0.0));
      sc.Camera = new StaticCamera(new Vector3d(0, 1.5, -2.5), new Vector3d(0, -0.5, 1), 60.0);
      return sc;
    }
    Assert.Equal(3, EmitterSet.Of(Scene().Intersectable).Count);
    FloatImage one = PathTracingTests.Render(Scene(), new PathTracing(), 24, 4, threads: 1);
    FloatImage two = PathTracingTests.Render(Scene(), new PathTracing(), 24, 4, threads: 2);
    FloatImage lists = PathTracingTests.Render(Scene(), new PathTracing(), 24, 4, threads: 2, accel: AccelMode.None);
    Assert.Equal(one.Data, two.Data);
    Assert.Equal(one.Data, lists.Data);
    Assert.NotEqual(one.Data, PathTracingTests.Render(Scene(), new PathTracing(), 24, 4, seed: 9).Data);
  }
}
