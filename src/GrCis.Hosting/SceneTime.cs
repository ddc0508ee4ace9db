using Rendering;

namespace GrCis.Hosting;

/// <summary>
/// Sets the time of a scene. A scene that is itself <see cref="ITimeDependent"/> (AnimatedRayScene)
/// propagates time on its own; for any other scene we follow the same order: animator first, then
/// intersectable, background, camera, lights.
/// </summary>
public static class SceneTime
{
  public static void Set(IRayScene scene, double time)
  {
    MT.time = time;
    if (scene is ITimeDependent whole)
    {
      whole.Time = time;
      return;
    }
    if (scene.Animator != null)
      scene.Animator.Time = time;
    if (scene.Intersectable is ITimeDependent i)
      i.Time = time;
    if (scene.Background is ITimeDependent b)
      b.Time = time;
    if (scene.Camera is ITimeDependent c)
      c.Time = time;
    if (scene.Sources != null)
      foreach (ILightSource l in scene.Sources)
        if (l is ITimeDependent lt)
          lt.Time = time;
  }
}
