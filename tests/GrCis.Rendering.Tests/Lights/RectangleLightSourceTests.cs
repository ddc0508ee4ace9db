using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Lights;

public class RectangleLightSourceTests
{
  static Intersection At(Vector3d point, Vector3d normal) => new() { CoordWorld = point, Normal = normal };

  /// <summary>The light's (u, v) of each of a pixel's samples, taken in the given order of ranks.</summary>
  static (double U, double V)[] Points(RectangleLightSource light, int total, int[] ranks)
  {
    Intersection i = At(Vector3d.Zero, Vector3d.UnitY);
    MT.InitThreadData();
    MT.StartPixel(5, 7, total);
    var points = new (double, double)[total];
    foreach (int r in ranks)
    {
      MT.StartSample(r);
      Assert.NotNull(light.GetIntensity(i, out Vector3d dir));
      // Corner (−2, 4, −1), edges 4·x and 2·z: the point's (u, v) on the light.
      points[r] = ((dir.X + 2.0) / 4.0, (dir.Z + 1.0) / 2.0);
    }
    return points;
  }

  [Fact]
  public void A_pixels_samples_take_one_stratum_of_each_edge_whatever_their_order()
  {
    var light = new RectangleLightSource(new Vector3d(-2, 4, -1), new Vector3d(4, 0, 0), new Vector3d(0, 0, 2), 1.0);
    int[] inOrder = Enumerable.Range(0, 16).ToArray();
    (double U, double V)[] points = Points(light, 16, inOrder);
    Assert.All(points, p => Assert.True(p.U >= 0 && p.U < 1 && p.V >= 0 && p.V < 1, $"{p} off the light"));
    Assert.Equal(16, points.Select(p => (int)(p.U * 16)).Distinct().Count());
    Assert.Equal(16, points.Select(p => (int)(p.V * 16)).Distinct().Count());
    // The same points when the samples come in another order or in passes (the demo's progressive rendering).
    Assert.Equal(points, Points(light, 16, inOrder.Reverse().ToArray()));
    Assert.Equal(points, Points(light, 16, new[] { 0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15 }));
  }
}
