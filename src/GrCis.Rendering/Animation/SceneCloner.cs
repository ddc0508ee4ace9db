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
    if (scene.Animator != null || scene.Intersectable is ITimeDependent || scene.Background is ITimeDependent || scene.Camera is ITimeDependent)
      return true;
    if (scene.Sources != null)
      foreach (ILightSource light in scene.Sources)
        if (light is ITimeDependent)
          return true;
    return false;
  }
}
