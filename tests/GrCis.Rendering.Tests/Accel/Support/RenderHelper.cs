using Rendering;
using Rendering.Accel;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Testing;

/// <summary>Renders a scene through one access path with the default Whitted ray tracer.</summary>
public static class RenderHelper
{
  public static FloatImage Render(IRayScene scene, AccelMode mode, int width, int height, int spp = 1, int threads = 1, bool rayCasting = false)
  {
    RayCasting f = rayCasting ? new RayCasting(scene) : new RayTracing(scene);
    f.Accel = mode;
    ImageSynthesizer renderer = spp <= 1
      ? new SimpleImageSynthesizer()
      : new SupersamplingImageSynthesizer { Supersampling = spp };
    renderer.Width = width;
    renderer.Height = height;
    return TileRenderer.Render(scene, f, renderer, new RenderOptions { Threads = threads, Seed = 7 });
  }
}
