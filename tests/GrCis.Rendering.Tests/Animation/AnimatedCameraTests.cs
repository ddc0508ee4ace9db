using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

public class AnimatedCameraTests
{
  static void AssertNear(Vector3d expected, Vector3d actual)
  {
    Assert.True((expected - actual).Length < 1e-9, $"expected {expected}, got {actual}");
  }

  [Fact]
  public void Camera_orbits_the_look_at_point_once_about_the_vertical_axis()
  {
    var lookAt = new Vector3d(1.0, 2.0, 3.0);
    var cam = new AnimatedCamera(lookAt, lookAt + new Vector3d(4.0, 1.0, 0.0), 50.0) { Start = 2.0, End = 6.0 };

    cam.Time = 2.0;
    AssertNear(lookAt + new Vector3d(4.0, 1.0, 0.0), cam.center);
    cam.Time = 3.0;
    AssertNear(lookAt + new Vector3d(0.0, 1.0, 4.0), cam.center);
    cam.Time = 4.0;
    AssertNear(lookAt + new Vector3d(-4.0, 1.0, 0.0), cam.center);
    cam.Time = 6.0;
    AssertNear(lookAt + new Vector3d(4.0, 1.0, 0.0), cam.center);
    AssertNear((lookAt - cam.center).Normalized(), cam.direction);
  }

  [Fact]
  public void Camera_looks_at_its_point_through_the_image_centre()
  {
    var lookAt = new Vector3d(0.0, 0.5, 0.0);
    var cam = new AnimatedCamera(lookAt, new Vector3d(0.0, 1.0, -5.0), 40.0) { Width = 64, Height = 48 };
    cam.Time = 3.7;
    Assert.True(cam.GetRay(32.0, 24.0, out Vector3d p0, out Vector3d p1));
    AssertNear((lookAt - p0).Normalized(), p1);
  }

  [Fact]
  public void Clone_keeps_size_and_time_and_moves_independently()
  {
    var cam = new AnimatedCamera(Vector3d.Zero, new Vector3d(0, 0, -5), 40.0) { Width = 64, Height = 48 };
    cam.Time = 1.0;
    var copy = (AnimatedCamera)cam.Clone();
    Assert.Equal(64.0, copy.Width);
    Assert.Equal(48.0, copy.Height);
    Assert.Equal(1.0, copy.Time);
    AssertNear(cam.center, copy.center);
    copy.Time = 5.0;
    Assert.Equal(1.0, cam.Time);
    Assert.NotEqual(cam.center, copy.center);
  }
}
