using System;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Lights;

public class SphereLightSourceTests
{
  static Intersection At(Vector3d point, Vector3d normal) => new() { CoordWorld = point, Normal = normal };

  [Fact]
  public void Zero_radius_lights_like_a_point_light()
  {
    var sphere = new SphereLightSource(new Vector3d(1, 4, 2), 0.0, 0.9);
    var point = new PointLightSource(new Vector3d(1, 4, 2), 0.9);
    Intersection i = At(Vector3d.Zero, Vector3d.UnitY);
    Assert.Equal(point.GetIntensity(i, out Vector3d a), sphere.GetIntensity(i, out Vector3d b));
    Assert.Equal(a, b);
  }

  [Fact]
  public void Samples_are_points_of_the_visible_cap_spread_over_the_pixels_samples()
  {
    var centre = new Vector3d(0, 5, 0);
    var light = new SphereLightSource(centre, 1.0, 1.0);
    Vector3d p = Vector3d.Zero;
    Intersection i = At(p, Vector3d.UnitY);
    MT.StartPixel(3, 3, 16);
    var points = Enumerable.Range(0, 16).Select(r =>
    {
      MT.StartSample(r);
      Assert.NotNull(light.GetIntensity(i, out Vector3d dir));
      return p + dir;
    }).ToArray();
    foreach (Vector3d q in points)
    {
      Assert.Equal(1.0, (q - centre).Length, 9);
      Assert.True(Vector3d.Dot(q - centre, p - centre) > 0.0, "a point on the far side of the light");
    }
    Assert.Equal(16, points.Distinct().Count());
    // Stratified over the cap: the mean point is near the cap's centre.
    Vector3d mean = points.Aggregate(Vector3d.Zero, (s, q) => s + q) / 16.0;
    Assert.True(Math.Abs(mean.X) < 0.15 && Math.Abs(mean.Z) < 0.15, $"mean {mean}");
  }

  [Fact]
  public void Dim_attenuates_by_distance_without_touching_the_lights_own_intensity()
  {
    var light = new SphereLightSource(new Vector3d(0, 3, 0), 0.0, 2.0) { Dim = new[] { 1.0, 0.0, 1.0 } };
    double[]? got = light.GetIntensity(At(Vector3d.Zero, Vector3d.UnitY), out _);
    Assert.Equal(2.0 / 10.0, got![0], 12);
    Assert.Equal(2.0, light.intensity[0]);
  }
}
