namespace GrCis.Interactive.Tests;

public class ZoomPanTests
{
  [Fact]
  public void Wheel_zoom_keeps_the_pixel_under_the_cursor()
  {
    var view = new ZoomPan();
    view.Pan(10, 20);
    Assert.True(view.TryPixelAt(110.5, 70.5, 640, 480, out int x0, out int y0));
    Assert.Equal((100, 50), (x0, y0));

    view.Wheel(110.5, 70.5, 3);

    Assert.Equal(ZoomPan.Step * ZoomPan.Step * ZoomPan.Step, view.Zoom, 12);
    (double ix, double iy) = view.ToImage(110.5, 70.5);
    Assert.Equal(100.5, ix, 9);
    Assert.Equal(50.5, iy, 9);
  }

  [Fact]
  public void Zoom_is_clamped_and_reset_restores_the_identity()
  {
    var view = new ZoomPan();
    int changes = 0;
    view.Changed += (_, _) => changes++;
    view.ZoomAt(0, 0, 1e6);
    Assert.Equal(ZoomPan.MaxZoom, view.Zoom);
    view.ZoomAt(0, 0, 1e-9);
    Assert.Equal(ZoomPan.MinZoom, view.Zoom);
    view.Pan(-3, 4);
    view.Reset();
    Assert.Equal((1.0, 0.0, 0.0), (view.Zoom, view.OffsetX, view.OffsetY));
    Assert.Equal(4, changes);
    Assert.Throws<System.ArgumentOutOfRangeException>(() => view.ZoomAt(0, 0, 0));
  }

  [Fact]
  public void Points_outside_the_image_have_no_pixel()
  {
    var view = new ZoomPan();
    view.ZoomAt(0, 0, 2);
    Assert.True(view.TryPixelAt(19.9, 0, 10, 10, out int x, out _));
    Assert.Equal(9, x);
    Assert.False(view.TryPixelAt(20, 0, 10, 10, out _, out _));
    Assert.False(view.TryPixelAt(-0.1, 5, 10, 10, out _, out _));
    Assert.Equal((0.0, 0.0, 20.0, 20.0), view.ImageBounds(10, 10));
  }
}
