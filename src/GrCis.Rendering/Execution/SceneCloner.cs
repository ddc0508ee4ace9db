using System;

namespace Rendering;

/// <summary>Per-worker copies of a scene ("clone on write").</summary>
public static class SceneCloner
{
  /// <summary>
  /// The scene a render worker should use: a clone when the scene has parts that change with
  /// time (so the worker can set its own time without disturbing others), otherwise the same
  /// instance, shared read-only.
  /// </summary>
  public static IRayScene CloneForWorker(IRayScene scene)
  {
    ArgumentNullException.ThrowIfNull(scene);
    return IsTimeDependent(scene) ? (IRayScene)((ITimeDependent)scene).Clone() : scene;
  }

  /// <summary>
  /// The scene a worker of one frame renders: the frame's scene itself, shared read-only, as GrCis shared a
  /// still's scene among its threads; a clone (<see cref="CloneForWorker(IRayScene)"/>) only when
  /// <paramref name="function"/> moves the time per sample (motion blur), so workers must not share it.
  /// A student's <c>Clone()</c> is often incomplete, so it is called only where GrCis would have called it.
  /// </summary>
  public static IRayScene ForFrameWorker(IRayScene scene, IImageFunction function)
  {
    ArgumentNullException.ThrowIfNull(scene);
    return MovesTime(function) ? CloneForWorker(scene) : scene;
  }

  /// <summary>True when <paramref name="function"/> sets the time of the worker's scene while it renders.</summary>
  public static bool MovesTime(IImageFunction? function) => function is MotionBlurImageFunction { Shutter: > 0.0 };

  /// <summary>Whether setting the scene's time can change anything a worker sees.</summary>
  public static bool IsTimeDependent(IRayScene scene) => scene switch
  {
    AnimatedRayScene animated => animated.HasTimeDependentParts,
    ITimeDependent => true,
    _ => false,
  };

  /// <summary>True when any part of <paramref name="scene"/> would change with time (the animator, geometry, background, camera or a light).</summary>
  public static bool HasTimeDependentParts(IRayScene scene)
  {
    ArgumentNullException.ThrowIfNull(scene);
    return AnimatedRayScene.AnyTimeDependentPart(scene);
  }
}
