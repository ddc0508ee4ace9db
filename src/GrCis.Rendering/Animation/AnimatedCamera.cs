using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A camera that circles its look-at point once over [Start, End], about the vertical (y)
/// axis through that point, always looking at it. At Start it is at the given centre; the
/// offset from the look-at point turns by the angle 2π (t − Start) / (End − Start), going from
/// +x towards +z (a quarter turn takes an offset along +x to +z). Start and End set the period,
/// not bounds: later times keep circling.
/// </summary>
[Serializable]
public class AnimatedCamera : StaticCamera, ITimeDependent
{
  /// <summary>The point the camera circles and looks at.</summary>
  protected Vector3d lookAt;

  /// <summary>Camera centre at time Start.</summary>
  protected Vector3d center0;

  /// <summary>The current time (<see cref="Time"/>).</summary>
  protected double time;

  /// <summary>A camera at <paramref name="cen"/> looking at <paramref name="lookat"/>, circling it once over the time range 0 to 10 s (change <see cref="Start"/> and <see cref="End"/> to change the period).</summary>
  /// <param name="lookat">The point the camera circles and looks at, in world coordinates.</param>
  /// <param name="cen">Position of the camera at time <see cref="Start"/>.</param>
  /// <param name="ang">Horizontal field of view in degrees.</param>
  public AnimatedCamera(Vector3d lookat, Vector3d cen, double ang)
    : base(cen, lookat - cen, ang)
  {
    lookAt = lookat;
    center0 = cen;
    Start = 0.0;
    End = 10.0;
    time = 0.0;
  }

  /// <summary>Time in seconds when the camera is at its initial position.</summary>
  public double Start { get; set; }

  /// <summary>Time in seconds when one full circle is done: End − Start is the period.</summary>
  public double End { get; set; }

  /// <summary>Current time in seconds; setting it moves the camera to its place on the circle.</summary>
  public double Time
  {
    get => time;
    set => setTime(value);
  }

  /// <summary>Moves the camera to its place on the orbit.</summary>
  protected virtual void setTime(double newTime)
  {
    time = newTime;
    double period = End - Start;
    double angle = period != 0.0 ? 2.0 * Math.PI * (time - Start) / period : 0.0;
    // Row vectors: rotating by −angle about y takes +x towards +z.
    Vector3d radial = Vector3d.TransformVector(center0 - lookAt, Matrix4d.CreateRotationY(-angle));
    center = lookAt + radial;
    direction = (-radial).Normalized();
    prepare();
  }

  /// <summary>An independent camera at the same time and image size (all state is values).</summary>
  public virtual object Clone() => MemberwiseClone();
}
