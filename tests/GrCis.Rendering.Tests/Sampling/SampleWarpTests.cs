using System;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Sampling;

public class SampleWarpTests
{
  static void Grid(int n, Action<double, double> each)
  {
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
        each((i + 0.5) / n, (j + 0.5) / n);
  }

  [Fact]
  public void Concentric_disk_is_inside_the_unit_disk_and_uniform_by_area()
  {
    int inner = 0, all = 0;
    Grid(200, (u, v) =>
    {
      Vector2d p = SampleWarp.ConcentricDisk(u, v);
      Assert.True(p.Length <= 1.0 + 1e-12);
      all++;
      if (p.Length < 0.5)
        inner++;
    });
    Assert.Equal(0.25, inner / (double)all, 2);
  }

  [Theory]
  [InlineData(0.0)]
  [InlineData(1.0)]
  [InlineData(10.0)]
  [InlineData(200.0)]
  public void Power_cosine_directions_are_unit_on_the_axis_side_with_mean_cosine_of_the_lobe(double exponent)
  {
    Vector3d axis = new Vector3d(1.0, 2.0, -0.5).Normalized();
    double sum = 0.0;
    int count = 0;
    Grid(100, (u, v) =>
    {
      Vector3d d = SampleWarp.PowerCosine(u, v, axis, exponent);
      Assert.Equal(1.0, d.Length, 12);
      double c = Vector3d.Dot(d, axis);
      Assert.True(c >= -1e-12);
      sum += c;
      count++;
    });
    // E[cos] under the density (e+1)/(2π) cos^e is (e+1)/(e+2).
    Assert.Equal((exponent + 1.0) / (exponent + 2.0), sum / count, 3);
  }

  [Theory]
  [InlineData(0.0)]
  [InlineData(3.0)]
  [InlineData(50.0)]
  public void Power_cosine_density_integrates_to_one_over_the_hemisphere(double exponent)
  {
    // Midpoint rule in (cos θ, φ): the solid angle element is d(cos θ) dφ.
    const int n = 4000;
    double integral = 0.0;
    for (int i = 0; i < n; i++)
    {
      double c = (i + 0.5) / n;
      integral += SampleWarp.PowerCosinePdf(c, exponent) * 2.0 * Math.PI / n;
    }
    Assert.Equal(1.0, integral, 3);
  }

  [Fact]
  public void Uniform_cone_stays_inside_the_cone()
  {
    Vector3d axis = Vector3d.UnitY;
    double cosMax = Math.Cos(0.3);
    Grid(50, (u, v) => Assert.True(Vector3d.Dot(SampleWarp.UniformCone(u, v, axis, cosMax), axis) >= cosMax - 1e-12));
  }

  [Fact]
  public void Frame_is_orthonormal_for_any_normal_including_the_poles()
  {
    foreach (Vector3d n in new[] { Vector3d.UnitZ, -Vector3d.UnitZ, Vector3d.UnitX, new Vector3d(0.3, -0.4, -0.866).Normalized() })
    {
      SampleWarp.Frame(n, out Vector3d t, out Vector3d b);
      Assert.Equal(1.0, t.Length, 12);
      Assert.Equal(1.0, b.Length, 12);
      Assert.Equal(0.0, Vector3d.Dot(t, n), 12);
      Assert.Equal(0.0, Vector3d.Dot(b, n), 12);
      Assert.Equal(0.0, Vector3d.Dot(t, b), 12);
    }
  }
}
