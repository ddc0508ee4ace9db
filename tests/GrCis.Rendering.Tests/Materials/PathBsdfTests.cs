using System;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Materials;

/// <summary>The path tracer's scattering: each lobe's sampling estimator integrates to the lobe's albedo, and the sampled densities match the evaluated ones.</summary>
public class PathBsdfTests
{
  static readonly Vector3d Up = Vector3d.UnitY;

  static PathBsdf Bsdf(double kd, double ks, int h, double kt = 0.0, double n = 1.5, double colour = 1.0, Vector3d? incoming = null)
  {
    var m = new PhongMaterial(new[] { colour, colour, colour }, 0.0, kd, ks, h) { Kt = kt, n = n };
    Vector3d d = (incoming ?? new Vector3d(0.3, -1.0, 0.2)).Normalized();
    return PathBsdf.For(m, m.Color, Up, d, 100000);
  }

  [Theory]
  [InlineData(0.8, 0.0, 1, 0.0)]        // Lambertian alone
  [InlineData(0.0, 0.6, 20, 0.0)]       // glossy alone
  [InlineData(0.0, 1.0, 1000000, 0.0)]  // ideal mirror alone
  [InlineData(0.0, 0.0, 1, 1.0)]        // dielectric alone
  public void A_one_lobe_surface_samples_the_same_whatever_its_lobe_choice_so_the_path_needs_none(double kd, double ks, int h, double kt)
  {
    PathBsdf b = Bsdf(kd, ks, h, kt);
    Assert.True(b.SingleLobe);
    foreach (double choice in new[] { 0.3, 0.999999 })
    {
      Assert.Equal(b.Sample(0.0, 0.37, 0.61, out Vector3d w0, out Rgb f0, out double p0, out bool d0),
                   b.Sample(choice, 0.37, 0.61, out Vector3d w1, out Rgb f1, out double p1, out bool d1));
      Assert.Equal((w0, f0.R, p0, d0), (w1, f1.R, p1, d1));
    }
    Assert.False(Bsdf(0.5, 0.3, 20).SingleLobe);
  }

  [Fact]
  public void An_ideal_mirror_alone_needs_no_direction_sample_and_other_surfaces_do()
  {
    PathBsdf mirror = Bsdf(0.0, 1.0, 1000000);
    Assert.False(mirror.SamplesDirection);
    mirror.Sample(0.0, 0.1, 0.9, out Vector3d a, out _, out _, out _);
    mirror.Sample(0.0, 0.8, 0.2, out Vector3d b, out _, out _, out _);
    Assert.Equal(a, b);
    Assert.True(Bsdf(0.8, 0.0, 1).SamplesDirection);
    Assert.True(Bsdf(0.0, 0.0, 1, kt: 1.0).SamplesDirection);   // its u chooses reflection or refraction
    Assert.True(Bsdf(0.3, 0.7, 1000000).SamplesDirection);
  }

  /// <summary>∫ f cos dω over the hemisphere by quadrature in (cos θ, φ), independent of the sampling code.</summary>
  static double Albedo(PathBsdf b)
  {
    const int nc = 1500, np = 600;
    double sum = 0.0;
    for (int i = 0; i < nc; i++)
    {
      double c = (i + 0.5) / nc, s = Math.Sqrt(1.0 - c * c);
      for (int j = 0; j < np; j++)
      {
        double phi = 2.0 * Math.PI * (j + 0.5) / np;
        var wi = new Vector3d(s * Math.Cos(phi), c, s * Math.Sin(phi));
        sum += b.Eval(wi).G * c;
      }
    }
    return sum * 2.0 * Math.PI / (nc * np);
  }

  /// <summary>Mean of the sampling weights f·cos/pdf over a stratified grid of sample points.</summary>
  static double SampledMean(PathBsdf b)
  {
    const int n = 300;
    double sum = 0.0;
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
      {
        double choice = ((i * n + j) * 0.6180339887498949) % 1.0;
        if (b.Sample(choice, (i + 0.5) / n, (j + 0.5) / n, out _, out Rgb w, out _, out _))
          sum += w.G;
      }
    return sum / (n * n);
  }

  [Theory]
  [InlineData(1.0, 0.0, 1, 0.73)]    // Lambertian, albedo 0.73
  [InlineData(0.0, 0.6, 20, 1.0)]    // normalised Phong lobe
  [InlineData(0.0, 1.0, 300, 1.0)]   // narrow lobe
  [InlineData(0.5, 0.4, 40, 0.8)]    // both lobes, chosen at random
  public void Sampling_estimator_integrates_to_the_albedo(double kd, double ks, int h, double colour)
  {
    PathBsdf b = Bsdf(kd, ks, h, colour: colour);
    double albedo = Albedo(b);
    Assert.Equal(albedo, SampledMean(b), 2);
    if (ks == 0.0)
      Assert.Equal(kd * colour, albedo, 3);
    Assert.True(albedo <= kd * colour + ks + 1e-3, $"albedo {albedo} exceeds kd·colour + ks");
  }

  [Fact]
  public void Normalised_Phong_at_normal_incidence_reflects_ks_times_the_lobe_fraction_above_the_surface()
  {
    // Lobe around the normal: ∫ ks (H+2)/(2π) cos^H α cos θ dω = ks exactly when α = θ.
    PathBsdf b = Bsdf(0.0, 0.7, 30, incoming: -Up);
    Assert.Equal(0.7, Albedo(b), 3);
  }

  [Fact]
  public void Pdf_integrates_to_the_probability_of_the_smooth_lobes()
  {
    PathBsdf b = Bsdf(0.3, 0.3, 15, kt: 0.3);
    const int nc = 1000, np = 400;
    double sum = 0.0;
    for (int i = 0; i < nc; i++)
    {
      double c = (i + 0.5) / nc, s = Math.Sqrt(1.0 - c * c);
      for (int j = 0; j < np; j++)
      {
        double phi = 2.0 * Math.PI * (j + 0.5) / np;
        sum += b.Pdf(new Vector3d(s * Math.Cos(phi), c, s * Math.Sin(phi)));
      }
    }
    sum *= 2.0 * Math.PI / (nc * np);
    // The three lobes weigh 0.3 each; the dielectric is a delta, so the smooth densities hold 2/3.
    Assert.Equal(2.0 / 3.0, sum, 2);
  }

  [Fact]
  public void Coefficients_summing_above_one_are_scaled_to_conserve_energy()
  {
    PathBsdf b = Bsdf(1.0, 1.0, 1);   // kd + ks = 2
    Assert.True(Albedo(b) <= 1.0 + 1e-3);
  }

  [Fact]
  public void Ideal_mirror_reflects_the_mirror_direction_with_weight_ks()
  {
    PathBsdf b = Bsdf(0.0, 0.9, 1000000, incoming: new Vector3d(1.0, -1.0, 0.0));
    Assert.False(b.HasSmooth);
    Assert.True(b.Sample(0.5, 0.3, 0.3, out Vector3d wi, out Rgb w, out double pdf, out bool delta));
    Assert.True(delta);
    Assert.Equal(0.0, pdf);
    Assert.Equal(0.9, w.G, 12);
    Assert.Equal(new Vector3d(1.0, 1.0, 0.0).Normalized().X, wi.X, 12);
    Assert.Equal(new Vector3d(1.0, 1.0, 0.0).Normalized().Y, wi.Y, 12);
  }

  [Fact]
  public void Dielectric_reflects_with_the_Fresnel_probability_and_refracts_by_Snell()
  {
    Vector3d d = new Vector3d(Math.Sin(0.6), -Math.Cos(0.6), 0.0);
    PathBsdf b = Bsdf(0.0, 0.0, 1, kt: 1.0, n: 1.5, incoming: d);
    int reflected = 0;
    const int n = 20000;
    double sinT = Math.Sin(0.6) / 1.5, cosT = Math.Sqrt(1 - sinT * sinT);
    for (int k = 0; k < n; k++)
    {
      Assert.True(b.Sample(0.5, (k + 0.5) / n, 0.5, out Vector3d wi, out Rgb w, out _, out bool delta));
      Assert.True(delta);
      Assert.Equal(1.0, w.G, 12);
      if (wi.Y > 0.0)
        reflected++;
      else
      {
        Assert.Equal(sinT, wi.X, 12);   // Snell: sin θt = sin θi / n
        Assert.Equal(-cosT, wi.Y, 12);
      }
    }
    double expected = PathBsdf.Fresnel(Math.Cos(0.6), cosT, 1.0 / 1.5);
    Assert.Equal(expected, reflected / (double)n, 3);
  }

  [Fact]
  public void Fresnel_is_four_percent_at_normal_incidence_on_glass_and_total_beyond_the_critical_angle()
  {
    Assert.Equal(0.04, PathBsdf.Fresnel(1.0, 1.0, 1.0 / 1.5), 12);
    // From inside glass at 60° (beyond the critical 41.8°) every sample reflects.
    Vector3d d = new Vector3d(Math.Sin(1.05), Math.Cos(1.05), 0.0);   // going up, hitting the surface from below
    PathBsdf b = Bsdf(0.0, 0.0, 1, kt: 1.0, n: 1.5, incoming: d);
    for (int k = 0; k < 100; k++)
    {
      Assert.True(b.Sample(0.5, (k + 0.5) / 100, 0.5, out Vector3d wi, out _, out _, out _));
      Assert.True(wi.Y < 0.0, "total internal reflection must send the ray back down");
    }
  }

  [Theory]
  [InlineData(0.8, 0.0, 1)]     // Lambertian alone
  [InlineData(0.0, 0.6, 20)]    // glossy alone
  [InlineData(0.5, 0.3, 8)]     // both
  [InlineData(0.4, 0.5, 1000000)]   // Lambertian and an ideal mirror (its delta lobe is not evaluated)
  public void Eval_and_pdf_above_the_surface_give_the_bits_of_the_tested_ones(double kd, double ks, int h)
  {
    PathBsdf b = Bsdf(kd, ks, h);
    var random = new Random(11);
    for (int k = 0; k < 500; k++)
    {
      var wi = new Vector3d(random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1).Normalized();
      double cos = Vector3d.Dot(wi, b.FacingNormal);
      if (cos <= 0.0)
      {
        Assert.True(b.Eval(wi).IsBlack);
        Assert.Equal(0.0, b.Pdf(wi));
        continue;
      }
      Rgb tested = b.Eval(wi), above = b.EvalAbove(wi);
      Assert.Equal((tested.R, tested.G, tested.B), (above.R, above.G, above.B));
      Assert.Equal(BitConverter.DoubleToInt64Bits(b.Pdf(wi)), BitConverter.DoubleToInt64Bits(b.PdfAbove(wi, cos)));
    }
  }
}
