using System;
using System.Collections.Generic;
using GrCis.Hosting;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Cli.Tests;

/// <summary>Tiny animated scenes registered for the tests only (through <see cref="CliEnvironment.ExtraScenes"/>).</summary>
internal static class TestAnimations
{
  /// <summary>A background whose red channel is Time / 10: a frame's time can be read off any pixel.</summary>
  sealed class TimeBackground : IBackground, ITimeDependent
  {
    public double Start { get; set; }
    public double End { get; set; } = 10;
    public double Time { get; set; }
    public object Clone() => MemberwiseClone();
    public long GetColor(Vector3d p1, double[] color)
    {
      color[0] = Time / 10.0;
      color[1] = color[2] = 0;
      return 1;
    }
  }

  /// <summary>Like <see cref="TimeBackground"/>, but throws from 2 s on (a scene that fails mid-animation).</summary>
  sealed class BrokenBackground : IBackground, ITimeDependent
  {
    public double Start { get; set; }
    public double End { get; set; } = 10;
    public double Time { get; set; }
    public object Clone() => MemberwiseClone();
    public long GetColor(Vector3d p1, double[] color)
    {
      if (Time >= 2.0)
      {
        // The first broken frame fails last: frames in parallel must still report it, not a later one.
        if (Time < 2.5)
          System.Threading.Thread.Sleep(200);
        throw new InvalidOperationException($"the background broke at t = {Time}");
      }
      color[0] = color[1] = color[2] = 0.5;
      return 1;
    }
  }

  /// <summary>Scene source with an optional script-like range (<see cref="ISceneTiming"/>).</summary>
  sealed class Source : ISceneSource, ISceneTiming
  {
    readonly Func<IRayScene> create;

    public Source(string name, Func<IRayScene> create, double? start = null, double? end = null, double? fps = null)
    {
      DisplayName = name;
      this.create = create;
      Start = start;
      End = end;
      Fps = fps;
    }

    public string DisplayName { get; }
    public string OutputStem => DisplayName;
    public double? Start { get; }
    public double? End { get; }
    public double? Fps { get; }
    public IRayScene CreateScene() => create();
  }

  /// <summary>Red = time / 10 everywhere; AnimatedRayScene over 0 to 10 s.</summary>
  public static IRayScene Clock() => new AnimatedRayScene
  {
    Start = 0,
    End = 10,
    Background = new TimeBackground(),
    Camera = new StaticCamera(Vector3d.Zero, Vector3d.UnitZ, 60),
    Intersectable = new CSGInnerNode(SetOperation.Union),
    Sources = new LinkedList<ILightSource>(),
  };

  /// <summary>A red unit sphere moving along x from −4 to 4 over 0 to 4 s, in front of black.</summary>
  public static IRayScene MovingSphere()
  {
    var animator = new PropertyAnimator { Start = 0.0, End = 4.0 };
    animator.newProperty("x", 0.0, 4.0, 4.0, PropertyAnimator.InterpolationStyle.Once,
      new List<Vector3d> { new(-12, 0, 0), new(-4, 0, 0), new(4, 0, 0), new(12, 0, 0) });
    var root = new AnimatedCSGInnerNode(SetOperation.Union);
    var mover = new AnimatedNodeTransform("x", null, Matrix4d.Identity);
    root.InsertChild(mover, Matrix4d.Identity);
    var sphere = new Sphere();
    sphere.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.0, 0.0 });
    mover.InsertChild(sphere, Matrix4d.Identity);
    return new AnimatedRayScene
    {
      Start = 0.0,
      End = 4.0,
      Animator = animator,
      Intersectable = root,
      BackgroundColor = new double[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0, 0, -8), Vector3d.UnitZ, 50.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(1.0) }),
    };
  }

  public static ISceneSource? Find(string name) => name switch
  {
    "test-clock" => new Source("test-clock", Clock),
    // The same scene whose "script" asks for 2 to 3 s at 4 fps.
    "test-clock-script" => new Source("test-clock-script", Clock, start: 2.0, end: 3.0, fps: 4.0),
    "test-moving" => new Source("test-moving", MovingSphere),
    "test-broken" => new Source("test-broken", () =>
    {
      var sc = (AnimatedRayScene)Clock();
      sc.Background = new BrokenBackground();
      return sc;
    }),
    _ => null,
  };
}
