using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Lights;

/// <summary>The light model's adapters: samples against analytic irradiance, the density a sample reports against PdfLi, and the choice by power.</summary>
public class LightModelTests
{
  static readonly Vector3d Up = Vector3d.UnitY;

  /// <summary>Irradiance at the origin (normal <paramref name="n"/>) from a polygon of uniform radiance <paramref name="l"/> wholly above the horizon (Lambert's formula).</summary>
  static double PolygonIrradiance(Vector3d[] corners, Vector3d n, double l)
  {
    double sum = 0.0;
    for (int k = 0; k < corners.Length; k++)
    {
      Vector3d a = corners[k].Normalized(), b = corners[(k + 1) % corners.Length].Normalized();
      Vector3d c = Vector3d.Cross(a, b);
      double angle = Math.Acos(Math.Clamp(Vector3d.Dot(a, b), -1.0, 1.0));
      sum += angle * Vector3d.Dot(n, c.Normalized());
    }
    return 0.5 * l * Math.Abs(sum);
  }

  /// <summary>Monte Carlo irradiance ∫ L cos θ dω at the origin by <see cref="ILight.SampleLi"/>, n×n stratified; also checks each sample's density against PdfLi.</summary>
  static double Irradiance(ILight light, Vector3d n, int strata, Func<LightSample, Vector3d> pointOf, Func<Vector3d, Vector3d> normalAt)
  {
    var ctx = new LightContext(Vector3d.Zero, n, null);
    var rnd = new Random(7);
    double sum = 0.0;
    for (int i = 0; i < strata; i++)
      for (int j = 0; j < strata; j++)
      {
        double u = (i + rnd.NextDouble()) / strata, v = (j + rnd.NextDouble()) / strata;
        if (!light.SampleLi(ctx, u, v, out LightSample s))
          continue;
        Assert.Equal(1.0, s.Wi.Length, 12);
        Assert.Equal(s.Distance, s.ToLight.Length, 1e-9 * s.Distance);
        Vector3d p = pointOf(s);
        Assert.Equal(s.Pdf, light.PdfLi(ctx, s.Wi, p, normalAt(p)), 1e-9 * s.Pdf);
        double cos = Math.Max(0.0, Vector3d.Dot(s.Wi, n));
        sum += s.L.G * cos / s.Pdf;
      }
    return sum / (strata * strata);
  }

  [Fact]
  public void Emissive_rectangle_samples_give_Lamberts_polygon_irradiance_and_their_density_is_PdfLi()
  {
    // A 2×1 rectangle 1.5 above the origin, tilted, facing down-ish; radiance 3.
    Vector3d corner = new(-0.7, 1.5, -0.2), e1 = new(2.0, 0.3, 0.0), e2 = new(0.0, 0.1, 1.0);
    Vector3d normal = Vector3d.Cross(e1, e2).Normalized();
    if (normal.Y > 0.0)
      normal = -normal;
    var light = new EmissiveRectangle(corner, e1, e2, normal, new Rgb(3.0));
    Assert.Equal(LightKind.Area, light.Kind);
    Assert.Equal(Math.PI * Vector3d.Cross(e1, e2).Length * 3.0, light.Power, 12);

    Vector3d n = new Vector3d(0.2, 1.0, 0.1).Normalized();
    double exact = PolygonIrradiance(new[] { corner, corner + e1, corner + e1 + e2, corner + e2 }, n, 3.0);
    double estimate = Irradiance(light, n, 64, s => s.ToLight, _ => normal);
    Assert.Equal(exact, estimate, 0.002 * exact);

    // Seen from behind it sends nothing, and a ray along its normal's side has no density.
    var behind = new EmissiveRectangle(corner, e1, e2, -normal, new Rgb(3.0));
    Assert.False(behind.SampleLi(new LightContext(Vector3d.Zero, n, null), 0.5, 0.5, out _));
    Assert.Equal(0.0, behind.PdfLi(new LightContext(Vector3d.Zero, n, null), Up, corner, -normal));
  }

  /// <summary>Solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom and Strackee).</summary>
  static double TriangleSolidAngle(Vector3d a, Vector3d b, Vector3d c)
  {
    double la = a.Length, lb = b.Length, lc = c.Length;
    double num = Vector3d.Dot(a, Vector3d.Cross(b, c));
    double den = la * lb * lc + Vector3d.Dot(a, b) * lc + Vector3d.Dot(a, c) * lb + Vector3d.Dot(b, c) * la;
    return Math.Abs(2.0 * Math.Atan2(num, den));
  }

  [Theory]
  [InlineData(0.4, 0.0)]    // above its centre
  [InlineData(0.05, 0.3)]   // close beside its edge: the 1/d² varies a lot over it
  public void Rectangle_light_is_sampled_uniformly_by_solid_angle_its_density_integrates_to_one_and_gives_Lamberts_irradiance(double height, double shift)
  {
    // A true rectangle (perpendicular edges), 0.5×0.4, tilted, facing down towards the origin; radiance 15.
    Vector3d e1 = new Vector3d(0.5, 0.0, 0.0), e2 = new Vector3d(0.0, 0.4 * Math.Sin(0.3), 0.4 * Math.Cos(0.3));
    Vector3d corner = new(-0.25 + shift, height, -0.2);
    Vector3d normal = Vector3d.Cross(e1, e2).Normalized();
    if (Vector3d.Dot(normal, -corner) < 0.0)
      normal = -normal;
    var light = new EmissiveRectangle(corner, e1, e2, normal, new Rgb(15.0));
    Vector3d[] quad = { corner, corner + e1, corner + e1 + e2, corner + e2 };
    double omega = TriangleSolidAngle(quad[0], quad[1], quad[2]) + TriangleSolidAngle(quad[0], quad[2], quad[3]);

    // Every sample lies on the rectangle, its density is 1/Ω (so it integrates to 1 over the rectangle) and is PdfLi's.
    var ctx = new LightContext(Vector3d.Zero, Up, null);
    var rnd = new Random(3);
    for (int k = 0; k < 2000; k++)
    {
      Assert.True(light.SampleLi(ctx, rnd.NextDouble(), rnd.NextDouble(), out LightSample s));
      Vector3d local = s.ToLight - corner;
      Assert.InRange(Vector3d.Dot(local, e1) / e1.LengthSquared, -1e-9, 1.0 + 1e-9);
      Assert.InRange(Vector3d.Dot(local, e2) / e2.LengthSquared, -1e-9, 1.0 + 1e-9);
      Assert.Equal(0.0, Vector3d.Dot(local, normal), 9);
      Assert.Equal(1.0 / omega, s.Pdf, 1e-9 / omega);
    }

    // Uniform by solid angle: the fraction of samples in each quarter of the rectangle is that quarter's solid angle over Ω.
    const int n = 64;
    var counts = new int[4];
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
      {
        light.SampleLi(ctx, (i + 0.5) / n, (j + 0.5) / n, out LightSample s);
        Vector3d local = s.ToLight - corner;
        int q = (Vector3d.Dot(local, e1) / e1.LengthSquared < 0.5 ? 0 : 1) + (Vector3d.Dot(local, e2) / e2.LengthSquared < 0.5 ? 0 : 2);
        counts[q]++;
      }
    for (int q = 0; q < 4; q++)
    {
      Vector3d c = corner + (q & 1) * 0.5 * e1 + (q >> 1) * 0.5 * e2, h1 = 0.5 * e1, h2 = 0.5 * e2;
      double part = TriangleSolidAngle(c, c + h1, c + h1 + h2) + TriangleSolidAngle(c, c + h1 + h2, c + h2);
      Assert.Equal(part / omega, counts[q] / (double)(n * n), 0.005);
    }

    // The estimator of the irradiance is Lambert's polygon formula.
    Vector3d up = Up;
    double exact = PolygonIrradiance(quad, up, 15.0);
    double estimate = Irradiance(light, up, 64, s => s.ToLight, _ => normal);
    Assert.Equal(exact, estimate, 0.003 * exact);
  }

  [Fact]
  public void Near_a_rectangle_light_its_solid_angle_samples_estimate_irradiance_with_less_variance_than_area_samples()
  {
    // A 1×1 light 0.2 above the point, off to one side: 1/d² and the cosines vary a lot over it.
    Vector3d corner = new(-0.2, 0.2, -0.5), e1 = new(1.0, 0.0, 0.0), e2 = new(0.0, 0.0, 1.0);
    var light = new EmissiveRectangle(corner, e1, e2, -Up, new Rgb(1.0));
    var ctx = new LightContext(Vector3d.Zero, Up, null);
    var rnd = new Random(11);
    double sumA = 0.0, sumA2 = 0.0, sumS = 0.0, sumS2 = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; k++)
    {
      double u = rnd.NextDouble(), v = rnd.NextDouble();
      // By area: the point corner + u e1 + v e2, density d²/(area cos θ_light).
      Vector3d p = corner + u * e1 + v * e2;
      double d2 = p.LengthSquared, d = Math.Sqrt(d2);
      double area = (p.Y / d) * (p.Y / d) / d2;   // L cos θ cos θ_light / (d²/area), area 1
      sumA += area;
      sumA2 += area * area;
      Assert.True(light.SampleLi(ctx, u, v, out LightSample s));
      double f = Math.Max(0.0, Vector3d.Dot(s.Wi, Up)) / s.Pdf;
      sumS += f;
      sumS2 += f * f;
    }
    double meanA = sumA / n, meanS = sumS / n;
    double varA = sumA2 / n - meanA * meanA, varS = sumS2 / n - meanS * meanS;
    // Both estimate Lambert's irradiance (within 4 standard errors), the solid-angle one with far less variance.
    double exact = PolygonIrradiance(new[] { corner, corner + e1, corner + e1 + e2, corner + e2 }, Up, 1.0);
    Assert.True(Math.Abs(meanA - exact) < 4.0 * Math.Sqrt(varA / n), $"by area {meanA}, exact {exact}");
    Assert.True(Math.Abs(meanS - exact) < 4.0 * Math.Sqrt(varS / n), $"by solid angle {meanS}, exact {exact}");
    Assert.True(varS < 0.1 * varA, $"variance by solid angle {varS}, by area {varA}");
  }

  [Fact]
  public void Emissive_sphere_samples_give_pi_L_sin2_theta_max_and_their_density_is_PdfLi()
  {
    Vector3d centre = new(0.3, 2.0, -0.4);
    const double r = 0.5, le = 2.0;
    var light = new EmissiveSphere(centre, r, new Rgb(le));
    Vector3d n = centre.Normalized();   // facing the centre: the whole cone is above the horizon
    double exact = Math.PI * le * r * r / centre.LengthSquared;
    double estimate = Irradiance(light, n, 64, s => s.ToLight, p => (p - centre) / r);
    Assert.Equal(exact, estimate, 0.002 * exact);
  }

  [Fact]
  public void Environment_samples_are_cosine_weighted_and_a_uniform_background_gives_pi_L()
  {
    var scene = new DefaultRayScene { BackgroundColor = new[] { 0.5, 2.0, 1.0 } };
    var light = new EnvironmentLight(scene, 3, 1.0);
    Assert.Equal(LightKind.Infinite, light.Kind);
    Assert.Equal(Math.PI * Math.PI * (0.5 + 2.0 + 1.0) / 3.0, light.Power, 12);
    Vector3d n = new Vector3d(1.0, 2.0, -0.5).Normalized();
    double estimate = Irradiance(light, n, 16, s => s.Wi, _ => default);
    Assert.Equal(Math.PI * 2.0, estimate, 1e-9);
    Assert.Equal(0.0, light.PdfLi(new LightContext(Vector3d.Zero, n, null), -n, default, default));
  }

  [Fact]
  public void GrCis_point_rectangle_and_sphere_lights_are_delta_lights_carrying_pi_I_with_their_attenuation()
  {
    var ctx = new LightContext(Vector3d.Zero, Up, null);

    ILight point = GrCisLight.For(new PointLightSource(new Vector3d(1, 2, 2), 1.5))!;
    Assert.Equal(LightKind.DeltaPosition, point.Kind);
    Assert.True(point.SampleLi(ctx, 0.3, 0.7, out LightSample s));
    Assert.Equal(3.0, s.Distance, 12);
    Assert.Equal(Math.PI * 1.5, s.L.R, 12);
    Assert.Equal(1.0, s.Pdf);
    Assert.Equal(0.0, point.PdfLi(ctx, s.Wi, s.ToLight, -s.Wi));
    Assert.False(point.SampleLi(new LightContext(Vector3d.Zero, -Up, null), 0.3, 0.7, out _));   // the unlit side

    var rectangle = new RectangleLightSource(new Vector3d(-1, 3, -1), new Vector3d(2, 0, 0), new Vector3d(0, 0, 2), 2.0);
    ILight area = GrCisLight.For(rectangle)!;
    Assert.True(area.SampleLi(ctx, 0.25, 0.75, out s));
    Assert.Equal(new Vector3d(-0.5, 3.0, 0.5), s.ToLight);
    double dist = s.ToLight.Length;
    Assert.Equal(Math.PI * 2.0 / (0.5 + dist * (1.0 + dist * 0.1)), s.L.G, 12);   // RectangleLightSource's default Dim

    var sphere = new SphereLightSource(new Vector3d(0, 4, 0), 1.0, 1.0);
    ILight ball = GrCisLight.For(sphere)!;
    Assert.True(ball.SampleLi(ctx, 0.6, 0.1, out s));
    Assert.Equal(1.0, (s.ToLight - new Vector3d(0, 4, 0)).Length, 9);   // a point of the sphere, on the near side
    Assert.True(s.Distance < 4.0);

    // A subclass (it may light differently) and a student's own light are not GrCis's: they are asked through GetIntensity.
    Assert.Null(GrCisLight.For(new DimmedLight(new Vector3d(0, 1, 0), 1.0)));
  }

  /// <summary>A student's light: a subclass of GrCis's point light that halves it.</summary>
  sealed class DimmedLight : PointLightSource
  {
    public DimmedLight(Vector3d pos, double intens) : base(pos, intens) { }

    public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
    {
      double[]? i = base.GetIntensity(intersection, out dir);
      return i == null ? null : new[] { i[0] / 2, i[1] / 2, i[2] / 2 };
    }
  }

  [Fact]
  public void A_custom_light_is_asked_with_the_facing_normal_and_the_hit_is_left_unchanged()
  {
    var light = new CustomLight(new DimmedLight(new Vector3d(0, -2, 0), 2.0));
    var hit = new Intersection { CoordWorld = Vector3d.Zero, Normal = Up };
    // Gathering on the lower side: the light below sees the facing normal (−y) and lights it.
    Assert.True(light.SampleLi(new LightContext(Vector3d.Zero, -Up, hit), 0.5, 0.5, out LightSample s));
    Assert.Equal(Math.PI * 1.0, s.L.R, 12);
    Assert.Equal(-Up, s.Wi);
    Assert.Equal(Up, hit.Normal);
    // Gathering on the upper side: unlit.
    Assert.False(light.SampleLi(new LightContext(Vector3d.Zero, Up, hit), 0.5, 0.5, out _));
  }

  sealed class FixedPower : ILight
  {
    public FixedPower(double power) => Power = power;
    public LightKind Kind => LightKind.DeltaPosition;
    public double Power { get; }
    public bool SampleLi(in LightContext ctx, double u, double v, out LightSample sample) { sample = default; return false; }
    public double PdfLi(in LightContext ctx, in Vector3d wi, in Vector3d point, in Vector3d normal) => 0.0;
    public Rgb Le(in Vector3d normal, in Vector3d direction) => Rgb.Zero;
  }

  [Fact]
  public void Lights_are_chosen_in_proportion_to_power_and_lights_of_no_power_never()
  {
    var lights = new ILight[] { new FixedPower(1.0), new FixedPower(0.0), new FixedPower(3.0), new FixedPower(6.0) };
    var sampler = new LightSampler(lights);
    Assert.Equal(3, sampler.Count);
    double[] expected = { 0.1, 0.0, 0.3, 0.6 };
    double sum = 0.0;
    for (int k = 0; k < lights.Length; k++)
    {
      Assert.Equal(expected[k], sampler.Probability(lights[k]), 12);
      sum += sampler.Probability(lights[k]);
    }
    Assert.Equal(1.0, sum, 12);

    // Uniform u: each light is chosen as often as its probability, and reports that probability.
    var counts = new Dictionary<ILight, int>(ReferenceEqualityComparer.Instance);
    const int n = 10000;
    for (int i = 0; i < n; i++)
    {
      ILight chosen = sampler.Sample((i + 0.5) / n, out double p)!;
      Assert.Equal(sampler.Probability(chosen), p);
      counts[chosen] = counts.GetValueOrDefault(chosen) + 1;
    }
    for (int k = 0; k < lights.Length; k++)
      Assert.Equal(expected[k], counts.GetValueOrDefault(lights[k]) / (double)n, 3);
    Assert.Null(new LightSampler(new ILight[] { new FixedPower(0.0) }).Sample(0.5, out _));
  }

  /// <summary>A union holding an emissive rectangle (2×1, facing +z, radiance 4), a sphere of radius <paramref name="r"/> at x = 3 and an infinite plane below.</summary>
  static (DefaultRayScene Scene, Plane Lamp, Sphere Ball) LitScene(double r)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var lamp = new Plane(-1.0, 1.0, -0.5, 0.5);
    var glow = new PhongMaterial(new double[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { 4.0, 4.0, 4.0 } };
    lamp.SetAttribute(PropertyName.MATERIAL, glow);
    root.InsertChild(lamp, Matrix4d.Identity);
    var ball = new Sphere();
    root.InsertChild(ball, Matrix4d.Scale(r) * Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
    root.InsertChild(new Plane(), Matrix4d.CreateTranslation(0.0, 0.0, -5.0));   // unbounded: not part of the size
    var scene = new DefaultRayScene { Intersectable = root, BackgroundColor = new[] { 1.0, 1.0, 1.0 } };
    return (scene, lamp, ball);
  }

  [Fact]
  public void Environment_power_is_the_flux_through_the_scenes_bounding_disk_and_grows_with_its_size()
  {
    // Bounded solids: the lamp's box [-1,1]×[-0.5,0.5]×0 and the ball's [3-r,3+r]×[-r,r]×[-r,r].
    double Expected(double r)
    {
      Vector3d min = new(-1.0, Math.Min(-0.5, -r), -r), max = new(3.0 + r, Math.Max(0.5, r), r);
      double radius = 0.5 * (max - min).Length;
      return Math.PI * radius * radius * Math.PI * 1.0;
    }
    foreach (double r in new[] { 1.0, 4.0 })
    {
      var (scene, _, _) = LitScene(r);
      SceneLights lights = SceneLights.Of(scene, scene.Intersectable, 3, sampleEnvironment: true);
      Assert.Equal(Expected(r), lights.Environment!.Power, 9);
    }
    // The bigger scene's background is the likelier choice against the same lamp.
    var (small, smallLamp, _) = LitScene(1.0);
    var (big, bigLamp, _) = LitScene(4.0);
    SceneLights s = SceneLights.Of(small, small.Intersectable, 3, true), b = SceneLights.Of(big, big.Intersectable, 3, true);
    Assert.True(b.Sampler.Probability(b.Environment!) > s.Sampler.Probability(s.Environment!));
    Assert.Equal(0.0, SceneBounds.Radius(new Plane()));
  }

  [Fact]
  public void A_ray_hitting_an_emitter_gets_its_radiance_from_the_light_model_on_the_emitting_side_only()
  {
    var (scene, lamp, ball) = LitScene(1.0);
    SceneLights lights = SceneLights.Of(scene, scene.Intersectable, 3, false);
    Vector3d down = -Vector3d.UnitZ;

    // The lamp is a sampled light: its own adapter answers, with the emission, and its density is that of its samples.
    var hit = new Intersection(lamp) { CoordWorld = new Vector3d(0.2, 0.1, 0.0), Normal = Vector3d.UnitZ, Material = lamp.GetAttribute(PropertyName.MATERIAL) as IMaterial };
    Rgb le = lights.Emitted(hit, down, out ILight? light);
    Assert.Equal(4.0, le.G);
    Assert.IsType<EmissiveRectangle>(light);
    Assert.Equal(le.R, light!.Le(hit.Normal, down).R);
    var from = new LightContext(new Vector3d(0.2, 0.1, 2.0), -Vector3d.UnitZ, null);
    Assert.Equal(light.PdfLi(from, down, hit.CoordWorld, hit.Normal), lights.Pdf(light, from, down, hit.CoordWorld, hit.Normal), 12);
    Assert.True(lights.Emitted(hit, -down, out _).IsBlack);   // from behind

    // An emissive material on a solid light sampling does not reach (here the ball): found by rays only, no density.
    var glow = new PhongMaterial(new double[] { 0.0, 0.0, 0.0 }, 0.0, 0.0, 0.0, 1) { Emission = new[] { 2.0, 3.0, 5.0 } };
    var other = new Intersection(ball) { Normal = Vector3d.UnitX, Material = glow };
    le = lights.Emitted(other, -Vector3d.UnitX, out light);
    Assert.Equal((2.0, 3.0, 5.0), (le.R, le.G, le.B));
    Assert.IsType<EmissiveSurface>(light);
    Assert.Equal(0.0, lights.Pdf(light!, from, -Vector3d.UnitX, default, Vector3d.UnitX));

    // A surface that emits nothing: no light.
    var plain = new Intersection(ball) { Normal = Vector3d.UnitX, Material = new PhongMaterial() };
    Assert.True(lights.Emitted(plain, -Vector3d.UnitX, out light).IsBlack);
    Assert.Null(light);
  }
}
