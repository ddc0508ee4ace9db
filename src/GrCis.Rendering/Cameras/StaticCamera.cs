using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A pinhole camera: position, viewing direction, up vector and horizontal field of view.
/// Image x grows to the right, y downwards; pixel (x, y) has its centre at (x + 0.5, y + 0.5).
/// </summary>
[Serializable]
public class StaticCamera : ICamera
{
  protected double width = Execution.RenderDefaults.Width;
  protected double height = Execution.RenderDefaults.Height;

  public Vector3d center;
  public Vector3d direction;
  public Vector3d up = Vector3d.UnitY;

  /// <summary>Horizontal field of view in radians.</summary>
  public double hAngle = 1.0;

  // Image plane at distance 1: upper-left corner and per-pixel steps.
  protected Vector3d origin, dx, dy;

  /// <summary>For subclasses that set <see cref="center"/>, <see cref="direction"/>, … themselves and then call <see cref="prepare"/>.</summary>
  public StaticCamera()
  {
  }

  public StaticCamera(Vector3d cen, Vector3d dir, double ang)
  {
    center = cen;
    direction = dir.Normalized();
    hAngle = AngleToRadians(ang);
    Width = 300;
    Height = 400;
  }

  public StaticCamera(Vector3d cen, Vector3d dir, Vector3d upv, double ang)
  {
    center = cen;
    direction = dir.Normalized();
    up = upv;
    hAngle = AngleToRadians(ang);
    Width = 300;
    Height = 400;
  }

  // GrCis converts degrees through single precision; keep that for identical images.
  static double AngleToRadians(double degrees) => MathHelper.DegreesToRadians((float)degrees);

  public double AspectRatio
  {
    get => width / height;
    set
    {
      if (value <= 0.0)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Aspect ratio must be positive.");
      height = width / value;
      prepare();
    }
  }

  public double Width
  {
    get => width;
    set
    {
      if (value <= 0.0)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Width must be positive.");
      width = value;
      prepare();
    }
  }

  public double Height
  {
    get => height;
    set
    {
      if (value <= 0.0)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Height must be positive.");
      height = value;
      prepare();
    }
  }

  /// <summary>Recomputes the image-plane frame after a change of size or orientation (GrCis's name; subclasses may override).</summary>
  protected virtual void prepare()
  {
    Vector3d left = Vector3d.Cross(direction, up).Normalized();
    Vector3d top = Vector3d.Cross(left, direction).Normalized();
    double halfWidth = Math.Tan(0.5 * hAngle);
    double halfHeight = halfWidth / AspectRatio;
    origin = center + direction + top * halfHeight + left * halfWidth;
    dx = left * (-2.0 * halfWidth / width);
    dy = top * (-2.0 * halfHeight / height);
  }

  public virtual bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1) => Ray(x, y, out p0, out p1);

  /// <summary>
  /// <see cref="GetRay"/> of this class itself: the prepared Whitted kernel calls it directly for a camera of
  /// exactly this type, without an interface call.
  /// </summary>
  internal bool Ray(double x, double y, out Vector3d p0, out Vector3d p1)
  {
    p0 = center;
    p1 = (origin + x * dx + y * dy - center).Normalized();
    return true;
  }
}
