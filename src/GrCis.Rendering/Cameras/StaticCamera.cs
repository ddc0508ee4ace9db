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
  /// <summary>Image width in pixels (<see cref="Width"/>); the constructors with arguments set 300.</summary>
  protected double width = Execution.RenderDefaults.Width;
  /// <summary>Image height in pixels (<see cref="Height"/>); the constructors with arguments set 400.</summary>
  protected double height = Execution.RenderDefaults.Height;

  /// <summary>Position of the camera (the pinhole) in world coordinates: every ray starts here.</summary>
  public Vector3d center;
  /// <summary>Viewing direction in world coordinates, through the middle of the image (the constructors normalise it).</summary>
  public Vector3d direction;
  /// <summary>The world's up direction for the camera (default +y): the image's top side lies towards it. It must not be parallel to <see cref="direction"/>.</summary>
  public Vector3d up = Vector3d.UnitY;

  /// <summary>Horizontal field of view in radians.</summary>
  public double hAngle = 1.0;

  // Image plane at distance 1: upper-left corner and per-pixel steps.
  /// <summary>
  /// The image plane at distance 1 in front of <see cref="center"/>, set by <see cref="prepare"/>: <c>origin</c> is the
  /// world point of image point (0, 0) (the upper-left corner), <c>dx</c> and <c>dy</c> the world steps of one pixel to the right and down.
  /// </summary>
  protected Vector3d origin, dx, dy;

  /// <summary>For subclasses that set <see cref="center"/>, <see cref="direction"/>, … themselves and then call <see cref="prepare"/>.</summary>
  public StaticCamera()
  {
  }

  /// <summary>A camera at <paramref name="cen"/> looking along <paramref name="dir"/>, up being +y, e.g. <c>new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0)</c>.</summary>
  /// <param name="cen">Position of the camera in world coordinates (<see cref="center"/>).</param>
  /// <param name="dir">Viewing direction (<see cref="direction"/>); any length, it is normalised.</param>
  /// <param name="ang">Horizontal field of view in degrees (kept in radians in <see cref="hAngle"/>).</param>
  public StaticCamera(Vector3d cen, Vector3d dir, double ang)
  {
    center = cen;
    direction = dir.Normalized();
    hAngle = AngleToRadians(ang);
    Width = 300;
    Height = 400;
  }

  /// <summary>A camera at <paramref name="cen"/> looking along <paramref name="dir"/> with the given up vector.</summary>
  /// <param name="cen">Position of the camera in world coordinates (<see cref="center"/>).</param>
  /// <param name="dir">Viewing direction (<see cref="direction"/>); any length, it is normalised.</param>
  /// <param name="upv">Up direction (<see cref="up"/>), not parallel to <paramref name="dir"/>.</param>
  /// <param name="ang">Horizontal field of view in degrees (kept in radians in <see cref="hAngle"/>).</param>
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

  /// <summary>Width / height of the image. Setting it keeps <see cref="Width"/> and changes <see cref="Height"/>.</summary>
  /// <exception cref="ArgumentOutOfRangeException">The value set is not positive.</exception>
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

  /// <summary>Width of the image in pixels; the renderer sets it to the image size. The field of view <see cref="hAngle"/> spans it.</summary>
  /// <exception cref="ArgumentOutOfRangeException">The value set is not positive.</exception>
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

  /// <summary>Height of the image in pixels; the renderer sets it to the image size. The vertical field of view follows from the aspect ratio.</summary>
  /// <exception cref="ArgumentOutOfRangeException">The value set is not positive.</exception>
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

  /// <summary>
  /// The ray from <see cref="center"/> through image point (x, y): <paramref name="p0"/> is the centre,
  /// <paramref name="p1"/> the unit direction. Always true.
  /// </summary>
  /// <param name="x">Horizontal image coordinate in pixels, 0 at the left edge (pixel i has its centre at i + 0.5).</param>
  /// <param name="y">Vertical image coordinate in pixels, 0 at the top edge.</param>
  /// <param name="p0">Origin of the ray (world coordinates).</param>
  /// <param name="p1">Direction of the ray, unit length.</param>
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
