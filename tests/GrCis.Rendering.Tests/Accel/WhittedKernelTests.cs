using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Distributed;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The prepared Whitted kernel and the teaching class's <see cref="RayTracing.shade"/> are the same algorithm: every
/// built-in scene gives the same bits, rays and hits through both, and the kernel is chosen only for functions that
/// keep Whitted's shading.
/// </summary>
public class WhittedKernelTests
{
  /// <summary>Overrides <c>shade</c> (by calling it): the renderer must sample it through the teaching class.</summary>
  internal sealed class TextbookRayTracing(IRayScene scene) : RayTracing(scene)
  {
    public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color) =>
      base.shade(depth, importance, ref p0, ref p1, color);
  }

  sealed class OwnShadows : RayTracing
  {
    protected override bool Occluded(Vector3d p0, Vector3d dir) => base.Occluded(p0, dir);
  }

  sealed class OwnSample : RayTracing
  {
    public override long GetSample(double x, double y, double[] color) => base.GetSample(x, y, color);
  }

  /// <summary>A subclass with its own mirrored direction (a hook the kernel asks the function for).</summary>
  internal sealed class WiderMirror : RayTracing
  {
    protected internal override bool ReflectionDirection(Intersection i, Vector3d mirror, int depth, out Vector3d direction)
    {
      direction = mirror + new Vector3d(0.0, 0.05, 0.0);
      return true;
    }
  }

  public static IEnumerable<object[]> SceneNames() => Scenes.Names.Select(n => new object[] { n });

  static (FloatImage Image, long Rays, long Hits) Render(IRayScene scene, RayTracing function, ImageSynthesizer synth)
  {
    var context = new RenderContext();
    FloatImage image = TileRenderer.Render(scene, function, synth, new RenderOptions { Threads = 2, TileSize = 8 }, context: context);
    return (image, context.Rays, context.Hits);
  }

  static void AssertSameBits(FloatImage expected, FloatImage actual, string what)
  {
    Assert.Equal(expected.Data.Length, actual.Data.Length);
    int differing = 0;
    for (int i = 0; i < expected.Data.Length; i++)
      if (BitConverter.SingleToInt32Bits(expected.Data[i]) != BitConverter.SingleToInt32Bits(actual.Data[i]))
        differing++;
    Assert.True(differing == 0, $"{what}: {differing} of {expected.Data.Length} values differ between the kernel and shade");
  }

  [Theory]
  [MemberData(nameof(SceneNames))]
  public void Kernel_and_textbook_shade_give_the_same_image_rays_and_hits(string name)
  {
    foreach (int spp in new[] { 1, 4 })
    {
      ImageSynthesizer Synth() => spp == 1
        ? new SimpleImageSynthesizer { Width = 40, Height = 30 }
        : new SupersamplingImageSynthesizer { Width = 40, Height = 30, Supersampling = spp };
      IRayScene a = Scenes.Create(name), b = Scenes.Create(name);
      var kernel = Render(a, new RayTracing(a), Synth());
      var textbook = Render(b, new TextbookRayTracing(b), Synth());
      AssertSameBits(kernel.Image, textbook.Image, $"{name}, {spp} spp");
      Assert.Equal(kernel.Rays, textbook.Rays);
      Assert.Equal(kernel.Hits, textbook.Hits);
    }
  }

  [Fact]
  public void Kernel_is_chosen_only_for_functions_that_keep_the_shading()
  {
    Assert.NotNull(WhittedKernel.For(new RayTracing()));
    Assert.NotNull(WhittedKernel.For(new DistributedRayTracing()));
    Assert.NotNull(WhittedKernel.For(new WiderMirror()));
    Assert.Null(WhittedKernel.For(new TextbookRayTracing(new DefaultRayScene())));
    Assert.Null(WhittedKernel.For(new OwnShadows()));
    Assert.Null(WhittedKernel.For(new OwnSample()));
    Assert.Null(WhittedKernel.For(new PathTracing()));
    Assert.Null(WhittedKernel.For(new RayCasting()));
    Assert.Null(WhittedKernel.For(new RayTracing { Accel = AccelMode.None }));
  }

  [Fact]
  public void A_kept_hook_of_a_subclass_decides_the_kernels_image()
  {
    // The kernel asks the function for the mirrored direction: the subclass's own must change the image as shade's does.
    IRayScene a = Scenes.Create("Five balls"), b = Scenes.Create("Five balls"), c = Scenes.Create("Five balls");
    var synth = () => new SimpleImageSynthesizer { Width = 40, Height = 30 };
    FloatImage plain = Render(a, new RayTracing(a), synth()).Image;
    FloatImage wider = Render(b, new WiderMirror { Scene = b }, synth()).Image;
    Assert.False(plain.Data.AsSpan().SequenceEqual(wider.Data));
    Assert.NotNull(WhittedKernel.For(new WiderMirror()));
    AssertSameBits(wider, Render(c, new WiderMirrorTextbook { Scene = c }, synth()).Image, "a subclass's mirror direction");
  }

  [Fact]
  public void Parts_changed_between_frames_are_read_by_the_next_frame()
  {
    // The kernel reads the library scene's camera, background and lights once per frame (BoundScene): a second frame
    // of the same function after the parts changed must see the new ones, as shade does.
    static void Change(DefaultRayScene scene)
    {
      scene.Camera = new StaticCamera(new Vector3d(0.7, 1.5, -6.0), new Vector3d(-0.1, -0.2, 1.0), 45.0) { Width = 40, Height = 30 };
      scene.Background = new DefaultBackground(new[] { 0.6, 0.1, 0.2 });
      scene.Sources = new LinkedList<ILightSource>();
      scene.Sources.Add(new AmbientLightSource(0.3));
      scene.Sources.Add(new PointLightSource(new Vector3d(3.0, 5.0, -4.0), 0.8));
    }
    var synth = () => new SimpleImageSynthesizer { Width = 40, Height = 30 };
    var a = (DefaultRayScene)Scenes.Create("Five balls");
    var b = (DefaultRayScene)Scenes.Create("Five balls");
    var function = new RayTracing(a);
    FloatImage before = Render(a, function, synth()).Image;
    Change(a);
    Change(b);
    FloatImage after = Render(a, function, synth()).Image;
    Assert.False(before.Data.AsSpan().SequenceEqual(after.Data));
    AssertSameBits(Render(b, new TextbookRayTracing(b), synth()).Image, after, "changed camera, background and lights");

    // On one thread (a probe samples on the caller's): the next frame's kernel must not reuse this thread's binding.
    var c = (DefaultRayScene)Scenes.Create("Five balls");
    c.Camera!.Width = 40;
    c.Camera.Height = 30;
    var f = new RayTracing(c);
    var first = new double[3];
    WhittedKernel.For(f)!.Sample(0.5, 0.5, first);
    Change(c);
    var kernel = new double[3];
    var textbook = new double[3];
    long hash = WhittedKernel.For(f)!.Sample(0.5, 0.5, kernel);
    Assert.Equal(f.GetSample(0.5, 0.5, textbook), hash);
    Assert.Equal(textbook, kernel);
    Assert.NotEqual(first, kernel);
  }

  /// <summary>A library light's subclass with a hash of its own that changes per call: the kernel must ask it per hit.</summary>
  sealed class OwnHashLight(Vector3d position, double intensity) : PointLightSource(position, intensity)
  {
    public int Calls, Total;

    public override int GetHashCode()
    {
      Total++;
      return 1000 + Calls++;
    }
  }

  [Fact]
  public void Kernel_samples_return_the_textbook_hash_with_library_and_other_lights()
  {
    // The kernel takes a library light's hash once per frame (BoundLight.Hash) and asks any other light per hit: every
    // sample's hash must be shade's, which asks each light per hit (the subclass's counter restarts for each sample, so
    // a sample's second lit hit gets another hash than its first).
    var scene = (DefaultRayScene)Scenes.Create("Two spheres");
    var own = new OwnHashLight(new Vector3d(3.0, 5.0, -4.0), 0.5);
    scene.Sources!.Add(own);
    scene.Camera!.Width = 40;
    scene.Camera.Height = 30;
    var function = new RayTracing(scene);
    var textbook = new TextbookRayTracing(scene);
    WhittedKernel kernel = WhittedKernel.For(function)!;
    var k = new double[3];
    var t = new double[3];
    var hashes = new HashSet<long>();
    for (int y = 0; y < 30; y += 2)
      for (int x = 0; x < 40; x += 2)
      {
        own.Calls = 0;
        long hash = kernel.Sample(x + 0.5, y + 0.5, k);
        own.Calls = 0;
        Assert.Equal(textbook.GetSample(x + 0.5, y + 0.5, t), hash);
        Assert.Equal(t, k);
        hashes.Add(hash);
      }
    // Lit hits were sampled (the subclass's light was asked for its hash), not only the background.
    Assert.True(own.Total > 100, $"own light asked {own.Total} times");
    Assert.True(hashes.Count > 10);
  }

  sealed class WiderMirrorTextbook : RayTracing
  {
    protected internal override bool ReflectionDirection(Intersection i, Vector3d mirror, int depth, out Vector3d direction)
    {
      direction = mirror + new Vector3d(0.0, 0.05, 0.0);
      return true;
    }

    public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color) =>
      base.shade(depth, importance, ref p0, ref p1, color);
  }
}
