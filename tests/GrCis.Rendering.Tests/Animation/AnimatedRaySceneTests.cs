using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

public class AnimatedRaySceneTests
{
  static (AnimatedRayScene scene, TimeLog log) RecordingScene()
  {
    var log = new TimeLog();
    var scene = new AnimatedRayScene
    {
      Start = 0.0,
      End = 10.0,
      Animator = new RecordingAnimator(log),
      Intersectable = new RecordingNode(log),
      Background = new RecordingBackground(log),
      Camera = new RecordingCamera(log),
      Sources = new List<ILightSource> { new RecordingLight(log, "light1"), new PointLightSource(Vector3d.One, 1.0), new RecordingLight(log, "light2") },
    };
    return (scene, log);
  }

  [Fact]
  public void Setting_time_reaches_animator_first_then_intersectable_background_camera_lights()
  {
    (AnimatedRayScene scene, TimeLog log) = RecordingScene();
    log.Entries.Clear();

    scene.Time = 2.5;

    Assert.Equal(new[] { "animator", "intersectable", "background", "camera", "light1", "light2" }, log.Entries);
    Assert.Equal(2.5, scene.Time);
    Assert.Equal(2.5, scene.Animator!.Time);
    Assert.Equal(2.5, ((ITimeDependent)scene.Camera!).Time);
  }

  [Fact]
  public void Time_is_clamped_to_start_and_end()
  {
    (AnimatedRayScene scene, _) = RecordingScene();
    scene.Time = 12.0;
    Assert.Equal(10.0, scene.Time);
    scene.Time = -1.0;
    Assert.Equal(0.0, scene.Time);
  }

  [Fact]
  public void Clone_copies_time_dependent_parts_and_shares_the_rest()
  {
    (AnimatedRayScene scene, _) = RecordingScene();
    var staticLight = scene.Sources!.ElementAt(1);
    scene.Time = 3.0;

    var clone = (AnimatedRayScene)scene.Clone();

    Assert.NotSame(scene.Animator, clone.Animator);
    Assert.NotSame(scene.Intersectable, clone.Intersectable);
    Assert.NotSame(scene.Background, clone.Background);
    Assert.NotSame(scene.Camera, clone.Camera);
    Assert.NotSame(scene.Sources, clone.Sources);
    Assert.NotSame(scene.Sources!.First(), clone.Sources!.First());
    Assert.Same(staticLight, clone.Sources!.ElementAt(1));
    Assert.Equal(3.0, clone.Time);
    Assert.Equal(3.0, clone.Animator!.Time);

    clone.Time = 7.0;
    Assert.Equal(3.0, scene.Time);
    Assert.Equal(3.0, scene.Animator!.Time);
    Assert.Equal(3.0, ((ITimeDependent)scene.Intersectable!).Time);
  }

  [Fact]
  public void Static_parts_of_an_animated_scene_are_shared_by_the_clone()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var camera = new StaticCamera(Vector3d.Zero, Vector3d.UnitZ, 60.0);
    var scene = new AnimatedRayScene { Intersectable = root, Camera = camera, Animator = new PropertyAnimator() };

    var clone = (AnimatedRayScene)scene.Clone();

    Assert.Same(root, clone.Intersectable);
    Assert.Same(camera, clone.Camera);
    Assert.Same(scene.Background, clone.Background);
  }

  [Fact]
  public void Worker_clone_is_the_same_instance_when_nothing_changes_with_time()
  {
    var still = new AnimatedRayScene { Intersectable = new CSGInnerNode(SetOperation.Union), Camera = new StaticCamera(Vector3d.Zero, Vector3d.UnitZ, 60.0) };
    var plain = new DefaultRayScene();
    (AnimatedRayScene animated, _) = RecordingScene();

    Assert.Same(still, SceneCloner.CloneForWorker(still));
    Assert.Same(plain, SceneCloner.CloneForWorker(plain));
    Assert.NotSame(animated, SceneCloner.CloneForWorker(animated));
  }
}
