using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>The front ends' decisions about script objects, asked of <see cref="LibraryTypes"/>.</summary>
public class LibraryTypesTests
{
  sealed class QuietTracing : RayTracing
  {
  }

  sealed class MyGrid : SupersamplingImageSynthesizer
  {
  }

  sealed class GrCisStyleRenderer : SimpleImageSynthesizer
  {
    public override void RenderPixel(int x, int y, double[] color) => base.RenderPixel(x, y, color);
  }

  [Fact]
  public void Only_the_library_ray_tracer_and_ray_caster_are_copied_by_their_settings()
  {
    Assert.True(LibraryTypes.IsCopyableRayCaster(new RayTracing()));
    Assert.True(LibraryTypes.IsCopyableRayCaster(new RayCasting()));
    Assert.False(LibraryTypes.IsCopyableRayCaster(new PathTracing()));   // settings of its own
    Assert.False(LibraryTypes.IsCopyableRayCaster(new QuietTracing()));   // a subclass may hold anything
  }

  [Fact]
  public void Only_the_library_grid_with_several_samples_takes_its_samples_in_passes()
  {
    Assert.True(LibraryTypes.TakesSamplesInPasses(new SupersamplingImageSynthesizer { Supersampling = 4 }));
    Assert.False(LibraryTypes.TakesSamplesInPasses(new SupersamplingImageSynthesizer { Supersampling = 1 }));
    Assert.False(LibraryTypes.TakesSamplesInPasses(new MyGrid { Supersampling = 4 }));
    Assert.False(LibraryTypes.TakesSamplesInPasses(new SimpleImageSynthesizer()));
  }

  [Fact]
  public void Library_classes_are_told_from_a_scripts()
  {
    Assert.True(LibraryTypes.IsLibraryClass(new SupersamplingImageSynthesizer()));
    Assert.False(LibraryTypes.IsLibraryClass(new MyGrid()));
    Assert.False(LibraryTypes.ReturnsDisplayPixels(typeof(MyGrid)));
    Assert.True(LibraryTypes.ReturnsDisplayPixels(typeof(GrCisStyleRenderer)));
    Assert.False(LibraryTypes.RendersOwnRectangles(typeof(GrCisStyleRenderer)));
  }
}
