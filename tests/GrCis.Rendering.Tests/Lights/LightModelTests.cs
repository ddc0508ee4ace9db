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
    var light = new EnvironmentLight(scene, 3);
    Assert.Equal(LightKind.Infinite, light.Kind);
    Assert.Equal(Math.PI * (0.5 + 2.0 + 1.0) / 3.0, light.Power, 12);
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
}
