using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>
/// The Whitted path calls the library's own scene, camera, background, lights, sphere and plane directly when the
/// object is of exactly that class (BoundScene, PreparedMember.Direct and the direct cores). A subclass or a class of a script's own
/// must still be called through its virtual or interface member: these tests render with such classes and check
/// that their overrides decide the image.
/// </summary>
public class LibraryTypeCallTests
{
  static DefaultRayScene Balls(DefaultRayScene scene, ICamera camera, ILightSource light)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.4, 0.2 }, 0.1, 0.6, 0.3, 16));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    var floor = new Plane();
    root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
    scene.Intersectable = root;
    scene.BackgroundColor = new[] { 0.1, 0.2, 0.3 };
    scene.Camera = camera;
    scene.Sources = new LinkedList<ILightSource>();
    scene.Sources.Add(new AmbientLightSource(0.5));
    scene.Sources.Add(light);
    return scene;
  }

  static StaticCamera Camera() => new(new Vector3d(0.0, 0.5, -5.0), new Vector3d(0.0, -0.1, 1.0), 50.0);

  static PointLightSource Light() => new(new Vector3d(-4.0, 4.0, -3.0), 1.0);

  static FloatImage Render(IRayScene scene, int spp = 4)
  {
    var synth = new SupersamplingImageSynthesizer { Width = 24, Height = 18, Supersampling = spp };
    return TileRenderer.Render(scene, new RayTracing(scene), synth, new RenderOptions { Threads = 2, TileSize = 8 });
  }

  static bool Same(FloatImage a, FloatImage b) => a.Data.AsSpan().SequenceEqual(b.Data);

  sealed class ShiftedCamera : StaticCamera
  {
    public ShiftedCamera() : base(new Vector3d(0.0, 0.5, -5.0), new Vector3d(0.0, -0.1, 1.0), 50.0) { }

    public override bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1) => base.GetRay(x + 3.0, y, out p0, out p1);
  }

  sealed class DimLight : PointLightSource
  {
    public DimLight() : base(new Vector3d(-4.0, 4.0, -3.0), 1.0) { }

    public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
    {
      base.GetIntensity(intersection, out dir);
      return new[] { 0.1, 0.1, 0.1 };
    }
  }

  sealed class RedBackground : DefaultBackground
  {
    public override long GetColor(Vector3d p1, double[] color)
    {
      for (int b = 0; b < color.Length; b++)
        color[b] = b == 0 ? 1.0 : 0.0;
      return 1L;
    }
  }

  /// <summary>A scene class that answers <see cref="IRayScene"/> itself, around a library scene.</summary>
  sealed class OwnScene(IRayScene inner) : IRayScene
  {
    public IIntersectable? Intersectable { get => inner.Intersectable; set => inner.Intersectable = value; }
    public IBackground? Background { get => inner.Background; set => inner.Background = value; }
    public double[]? BackgroundColor { get => inner.BackgroundColor; set => inner.BackgroundColor = value; }
    public ICamera? Camera { get => inner.Camera; set => inner.Camera = value; }
    public ICollection<ILightSource>? Sources { get => inner.Sources; set => inner.Sources = value; }
  }

  [Fact]
  public void A_camera_subclass_overriding_GetRay_decides_the_rays()
  {
    FloatImage library = Render(Balls(new DefaultRayScene(), Camera(), Light()));
    FloatImage shifted = Render(Balls(new DefaultRayScene(), new ShiftedCamera(), Light()));
    Assert.False(Same(library, shifted));
    // The subclass without an override of its own renders as the library class.
    Assert.True(Same(library, Render(Balls(new DefaultRayScene(), new PlainCameraSubclass(), Light()))));
  }

  sealed class PlainCameraSubclass : StaticCamera
  {
    public PlainCameraSubclass() : base(new Vector3d(0.0, 0.5, -5.0), new Vector3d(0.0, -0.1, 1.0), 50.0) { }
  }

  [Fact]
  public void A_light_subclass_overriding_GetIntensity_decides_the_light()
  {
    FloatImage library = Render(Balls(new DefaultRayScene(), Camera(), Light()));
    FloatImage dim = Render(Balls(new DefaultRayScene(), Camera(), new DimLight()));
    Assert.False(Same(library, dim));
    Assert.True(dim.Data.AsSpan().IndexOfAnyExcept(0f) >= 0);
  }

  [Fact]
  public void A_background_subclass_overriding_GetColor_colours_the_misses()
  {
    DefaultRayScene scene = Balls(new DefaultRayScene(), Camera(), Light());
    scene.Background = new RedBackground();
    FloatImage image = Render(scene, 1);
    // The top row sees only the sky: every pixel is the subclass's red.
    Span<double> c = stackalloc double[3];
    for (int x = 0; x < image.Width; x++)
    {
      image.GetPixel(x, 0, c);
      Assert.Equal(1.0, c[0]);
      Assert.Equal(0.0, c[1]);
    }
  }

  [Fact]
  public void A_scene_class_of_its_own_renders_as_the_library_scene_it_wraps()
  {
    FloatImage library = Render(Balls(new DefaultRayScene(), Camera(), Light()));
    FloatImage own = Render(new OwnScene(Balls(new DefaultRayScene(), Camera(), Light())));
    Assert.True(Same(library, own));
  }

  [Fact]
  public void An_animated_scene_renders_as_the_default_scene()
  {
    FloatImage library = Render(Balls(new DefaultRayScene(), Camera(), Light()));
    FloatImage animated = Render(Balls(new AnimatedRayScene(), Camera(), Light()));
    Assert.True(Same(library, animated));
  }
}
