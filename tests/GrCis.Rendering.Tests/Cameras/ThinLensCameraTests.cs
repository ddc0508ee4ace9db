using System;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Cameras;

public class ThinLensCameraTests
{
  static readonly Vector3d Eye = new(0.7, 0.5, -5.0), Dir = new(0.0, -0.18, 1.0);

  [Fact]
  public void Zero_lens_radius_gives_the_pinhole_cameras_rays()
  {
    var pin = new StaticCamera(Eye, Dir, 50.0) { Width = 64, Height = 48 };
    var lens = new ThinLensCamera(Eye, Dir, 50.0) { Width = 64, Height = 48 };
    for (double x = 0.5; x < 64; x += 7.3)
    {
      pin.GetRay(x, 11.2, out Vector3d a0, out Vector3d a1);
      lens.GetRay(x, 11.2, out Vector3d b0, out Vector3d b1);
      Assert.Equal(a0, b0);
      Assert.Equal(a1, b1);
    }
  }

  [Fact]
  public void Every_lens_ray_starts_on_the_lens_and_passes_through_the_pinhole_rays_point_of_focus()
  {
    var pin = new StaticCamera(Eye, Dir, 50.0) { Width = 64, Height = 48 };
    var lens = new ThinLensCamera(Eye, Dir, 50.0, 0.2, 4.0) { Width = 64, Height = 48 };
    pin.GetRay(20.5, 30.5, out _, out Vector3d p1);
    Vector3d focus = Eye + p1 * (4.0 / Vector3d.Dot(p1, Dir.Normalized()));
    MT.StartPixel(20, 30, 16);
    double spread = 0.0;
    for (int r = 0; r < 16; r++)
    {
      MT.StartSample(r);
      lens.GetRay(20.5, 30.5, out Vector3d q0, out Vector3d q1);
      Vector3d offset = q0 - Eye;
      Assert.True(offset.Length <= 0.2 + 1e-12, "ray starts outside the lens");
      Assert.Equal(0.0, Vector3d.Dot(offset, Dir.Normalized()), 12);   // on the lens plane
      Vector3d toFocus = focus - q0;
      Assert.Equal(1.0, Vector3d.Dot(q1, toFocus.Normalized()), 12);
      spread = Math.Max(spread, offset.Length);
    }
    Assert.True(spread > 0.1, "16 stratified lens samples should reach the outer part of the lens");
  }

  [Fact]
  public void Focus_on_a_point_sets_the_distance_along_the_view_direction()
  {
    var lens = new ThinLensCamera(Vector3d.Zero, Vector3d.UnitZ, 40.0);
    lens.FocusOn(new Vector3d(1.0, 2.0, 7.5));
    Assert.Equal(7.5, lens.FocusDistance, 12);
  }

  [Fact]
  public void Bad_lens_settings_are_refused_with_a_message()
  {
    var lens = new ThinLensCamera(Vector3d.Zero, Vector3d.UnitZ, 40.0);
    Assert.Contains("lens radius", Assert.Throws<ArgumentOutOfRangeException>(() => lens.LensRadius = -1).Message);
    Assert.Contains("focus distance", Assert.Throws<ArgumentOutOfRangeException>(() => lens.FocusDistance = 0).Message);
  }
}
