using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Cameras;

public class StaticCameraTests
{
  static StaticCamera Camera() => new(new Vector3d(0, 0, -10), new Vector3d(0, 0, 1), 60) { Width = 640, Height = 480 };

  [Fact]
  public void Image_centre_looks_along_the_view_direction()
  {
    Camera().GetRay(320, 240, out Vector3d p0, out Vector3d p1);
    Assert.Equal(new Vector3d(0, 0, -10), p0);
    Assert.True((p1 - Vector3d.UnitZ).Length < 1e-12);
  }

  [Fact]
  public void Angle_is_the_horizontal_field_of_view()
  {
    Camera().GetRay(640, 240, out _, out Vector3d right);
    Camera().GetRay(0, 240, out _, out Vector3d left);
    double angle = Vector3d.CalculateAngle(left, right);
    Assert.Equal(60.0, MathHelper.RadiansToDegrees(angle), 5);
  }

  [Fact]
  public void X_grows_right_and_y_grows_down()
  {
    StaticCamera c = Camera();
    c.GetRay(600, 240, out _, out Vector3d right);
    c.GetRay(320, 20, out _, out Vector3d top);
    Assert.True(right.X > 0, "pixels to the right look towards +x (left-handed screen: +x right when looking along +z)");
    Assert.True(top.Y > 0, "row 0 is the top of the image");
  }

  [Fact]
  public void Rays_are_normalised()
  {
    Camera().GetRay(13.5, 400.25, out _, out Vector3d p1);
    Assert.Equal(1.0, p1.Length, 14);
  }
}
