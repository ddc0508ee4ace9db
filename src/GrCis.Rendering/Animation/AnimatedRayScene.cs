using System;
using System.Collections.Generic;

namespace Rendering;

/// <summary>
/// A ray scene that changes with time. Setting <see cref="Time"/> passes it on to the parts
/// that are time-dependent in a fixed order: the animator first (other parts read their
/// values from it), then the intersectable, background, camera and lights.
/// </summary>
/// <remarks>
/// <see cref="Clone"/> is "clone on write": the time-dependent parts are cloned, everything
/// else is shared read-only, so each render worker can hold its own clone at its own time.
/// </remarks>
[Serializable]
public class AnimatedRayScene : DefaultRayScene, ITimeDependent
{
  /// <summary>The current time (<see cref="Time"/>).</summary>
  protected double time;

  /// <summary>An empty animated scene with the time range 0 to 10 s.</summary>
  public AnimatedRayScene()
  {
    Start = 0.0;
    End = 10.0;
  }

  /// <inheritdoc/>
  public double Start { get; set; }

  /// <inheritdoc/>
  public double End { get; set; }

  /// <summary>Current time, clamped to [Start, End].</summary>
  public double Time
  {
    get => time;
    set => setTime(value);
  }

  /// <summary>Stores the time and propagates it. Override for something nonstandard.</summary>
  protected virtual void setTime(double newTime)
  {
    time = Math.Clamp(newTime, Math.Min(Start, End), Math.Max(Start, End));

    // Objects that look up their values through MT.scene (as GrCis nodes do) must find this
    // scene even when time is set outside a render worker.
    Execution.WorkerContext worker = Execution.WorkerContext.Current;
    IRayScene? previous = WorkerScene.Of(worker);
    WorkerScene.Set(worker, this);
    try
    {
      if (Animator != null)
        Animator.Time = time;
      if (Intersectable is ITimeDependent intersectable)
        intersectable.Time = time;
      if (Background is ITimeDependent background)
        background.Time = time;
      if (Camera is ITimeDependent camera)
        camera.Time = time;
      if (Sources != null)
        foreach (ILightSource light in Sources)
          if (light is ITimeDependent l)
            l.Time = time;
    }
    finally
    {
      WorkerScene.Set(worker, previous);
    }
  }

  /// <summary>True when any part would change with time (the animator, geometry, background, camera or a light).</summary>
  public virtual bool HasTimeDependentParts => AnyTimeDependentPart(this);

  /// <summary>True when any part of <paramref name="scene"/> would change with time (the animator, geometry, background, camera or a light).</summary>
  internal static bool AnyTimeDependentPart(IRayScene scene)
  {
    if (scene.Animator != null || scene.Intersectable is ITimeDependent || scene.Background is ITimeDependent || scene.Camera is ITimeDependent)
      return true;
    if (scene.Sources != null)
      foreach (ILightSource light in scene.Sources)
        if (light is ITimeDependent)
          return true;
    return false;
  }

  /// <summary>A scene at the same time with its own copies of the time-dependent parts; the rest is shared.</summary>
  public virtual object Clone()
  {
    var sc = (AnimatedRayScene)MemberwiseClone();
    sc.Animator = (ITimeDependent?)Animator?.Clone();
    if (Intersectable is ITimeDependent intersectable)
      sc.Intersectable = (IIntersectable)intersectable.Clone();
    if (Background is ITimeDependent background)
      sc.Background = (IBackground)background.Clone();
    if (Camera is ITimeDependent camera)
      sc.Camera = (ICamera)camera.Clone();
    sc.BackgroundColor = (double[]?)BackgroundColor?.Clone();
    if (Sources != null)
    {
      var lights = new List<ILightSource>(Sources.Count);
      foreach (ILightSource light in Sources)
        lights.Add(light is ITimeDependent l ? (ILightSource)l.Clone() : light);
      sc.Sources = lights;
    }
    sc.setTime(time);
    return sc;
  }
}
