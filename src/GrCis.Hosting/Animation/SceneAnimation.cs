using Rendering;

namespace GrCis.Hosting;

/// <summary>Puts a scene in the shape the animation pipeline needs: time reaches it through <see cref="ITimeDependent"/>.</summary>
public static class SceneAnimation
{
  /// <summary>
  /// The scene itself when it is <see cref="ITimeDependent"/> or has nothing that moves; otherwise an
  /// <see cref="AnimatedRayScene"/> over the same parts, so a <see cref="DefaultRayScene"/> whose
  /// animator, solids, camera or lights are time-dependent animates too (and is cloned per worker).
  /// </summary>
  public static IRayScene AsTimeDependent(IRayScene scene)
  {
    if (scene is ITimeDependent || !SceneCloner.HasTimeDependentParts(scene))
      return scene;
    var animated = new AnimatedRayScene
    {
      Animator = scene.Animator,
      Intersectable = scene.Intersectable,
      Background = scene.Background,
      BackgroundColor = scene.BackgroundColor,
      Camera = scene.Camera,
      Sources = scene.Sources,
    };
    if (scene.Animator != null)
    {
      animated.Start = scene.Animator.Start;
      animated.End = scene.Animator.End;
    }
    return animated;
  }
}
