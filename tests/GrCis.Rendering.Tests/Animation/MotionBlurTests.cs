using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Animation;

public class MotionBlurTests
{
  const int Size = 24;

  /// <summary>A red unit sphere moving along x (x = t) in front of a black background.</summary>
  static AnimatedRayScene MovingSphere()
  {
    var animator = new PropertyAnimator { Start = 0.0, End = 4.0 };
    animator.newProperty("x", 0.0, 4.0, 4.0, PropertyAnimator.InterpolationStyle.Once,
      new List<Vector3d> { new(-4, 0, 0), new(0, 0, 0), new(4, 0, 0), new(8, 0, 0) });
    var root = new AnimatedCSGInnerNode(SetOperation.Union);
    var mover = new AnimatedNodeTransform("x", null, Matrix4d.Identity);
    root.InsertChild(mover, Matrix4d.Identity);
    var sphere = new TestSphere();
    sphere.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.0, 0.0 });
    mover.InsertChild(sphere, Matrix4d.Identity);
    return new AnimatedRayScene
    {
      Start = 0.0,
      End = 4.0,
      Animator = animator,
      Intersectable = root,
      BackgroundColor = new double[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0.5, 0, -6), Vector3d.UnitZ, 40.0),
    };
  }

  static FloatImage Render(IRayScene scene, double time, double shutter, int threads, long seed = 7, double jitter = 1.0)
  {
    ((ITimeDependent)scene).Time = time;
    var blur = new MotionBlurImageFunction(new RayCasting()) { FrameTime = time, Shutter = shutter, Fps = 1.0 };
    var synth = new SupersamplingImageSynthesizer { Width = Size, Height = Size, Supersampling = 16, Jittering = jitter };
    return TileRenderer.Render(scene, blur, synth, new RenderOptions { Threads = threads, TileSize = 4, Seed = seed });
  }

  static double MaxDifference(FloatImage a, FloatImage b)
  {
    double max = 0.0;
    double[] ca = new double[a.Bands], cb = new double[b.Bands];
    for (int y = 0; y < a.Height; y++)
      for (int x = 0; x < a.Width; x++)
      {
        a.GetPixel(x, y, ca);
        b.GetPixel(x, y, cb);
        for (int i = 0; i < ca.Length; i++)
          max = System.Math.Max(max, System.Math.Abs(ca[i] - cb[i]));
      }
    return max;
  }

  /// <summary>Pixels neither fully background nor fully sphere.</summary>
  static int PartialPixels(FloatImage img)
  {
    int n = 0;
    double[] c = new double[img.Bands];
    for (int y = 0; y < img.Height; y++)
      for (int x = 0; x < img.Width; x++)
      {
        img.GetPixel(x, y, c);
        if (c[0] > 0.01 && c[0] < 0.99)
          n++;
      }
    return n;
  }

  [Fact]
  public void Blurred_frame_is_identical_for_any_thread_count()
  {
    AnimatedRayScene scene = MovingSphere();
    FloatImage one = Render(scene, 1.0, 1.0, threads: 1);
    FloatImage four = Render(scene, 1.0, 1.0, threads: 4);
    FloatImage again = Render(scene, 1.0, 1.0, threads: 3);
    Assert.Equal(0.0, MaxDifference(one, four));
    Assert.Equal(0.0, MaxDifference(one, again));
  }

  [Fact]
  public void Moving_object_is_blurred_and_the_original_scene_keeps_its_time()
  {
    AnimatedRayScene scene = MovingSphere();
    FloatImage still = Render(scene, 1.0, 0.0, threads: 2);
    FloatImage blurred = Render(scene, 1.0, 1.0, threads: 2);
    Assert.True(MaxDifference(still, blurred) > 0.2);
    Assert.True(PartialPixels(blurred) > 2 * PartialPixels(still), $"blurred {PartialPixels(blurred)} vs still {PartialPixels(still)} partial pixels");
    Assert.Equal(1.0, scene.Time);
  }

  [Fact]
  public void Shutter_changes_nothing_when_nothing_moves()
  {
    AnimatedRayScene scene = MovingSphere();
    scene.Animator = new PropertyAnimator();   // no "x" property: the sphere stays at rest
    // Without jitter the synthesizer draws no random numbers, so only time could differ.
    FloatImage still = Render(scene, 1.0, 0.0, threads: 2, jitter: 0.0);
    FloatImage blurred = Render(scene, 1.0, 1.0, threads: 2, jitter: 0.0);
    Assert.Equal(0.0, MaxDifference(still, blurred));
  }

  [Fact]
  public void Sample_times_are_stratified_over_the_shutter_interval()
  {
    var f = new MotionBlurImageFunction(new RayCasting()) { FrameTime = 2.0, Shutter = 0.5, Fps = 25.0 };
    double length = 0.5 / 25.0;
    Assert.Equal(2.0, f.SampleTime(0, 4, 0.0));
    Assert.Equal(2.0 + 0.25 * length, f.SampleTime(1, 4, 0.0), 15);
    Assert.Equal(2.0 + 0.875 * length, f.SampleTime(3, 4, 0.5), 15);
    Assert.True(f.SampleTime(3, 4, 0.999999) < 2.0 + length);
  }

  [Fact]
  public void A_function_bound_to_the_shared_scene_is_reported()
  {
    AnimatedRayScene scene = MovingSphere();
    var blur = new MotionBlurImageFunction(new RayCasting(scene)) { FrameTime = 1.0, Shutter = 1.0, Fps = 1.0 };
    var synth = new SupersamplingImageSynthesizer { Width = 4, Height = 4, Supersampling = 1 };
    var e = Assert.Throws<RenderException>(() => TileRenderer.Render(scene, blur, synth, new RenderOptions { Threads = 1 }));
    Assert.Contains("without a scene", e.InnerException!.Message);
  }
}
