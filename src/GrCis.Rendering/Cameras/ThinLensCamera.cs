using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// A thin-lens camera for depth of field: a <see cref="StaticCamera"/> whose rays start on a lens disk of
/// radius <see cref="LensRadius"/> and meet in the plane of sharp focus, <see cref="FocusDistance"/> in front of
/// the camera (measured along <see cref="StaticCamera.direction"/>). The lens points of a pixel's samples are
/// stratified (<see cref="Strata"/>), so n×n supersampling gives n×n well-spread lens points. Radius 0 is the
/// pinhole camera, ray for ray.
/// </summary>
/// <example><code>
/// scene.Camera = new ThinLensCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0)
/// {
///   LensRadius = 0.08,
///   FocusDistance = 5.0,
/// };
/// </code></example>
[Serializable]
public class ThinLensCamera : StaticCamera
{
  /// <summary>The stratification dimension of the lens (<see cref="Strata.Dimension(SampleDimension, int)"/>).</summary>
  public static readonly uint LensDimension = Strata.Dimension(SampleDimension.Lens, 0);

  double lensRadius;
  double focusDistance = 1.0;

  // Lens-plane axes (to the right and up in the image) and the unit viewing direction, kept by prepare().
  Vector3d lensRight, lensUp, viewAxis;

  /// <summary>For subclasses that set the fields themselves and then call prepare() (as with <see cref="StaticCamera()"/>).</summary>
  public ThinLensCamera()
  {
  }

  /// <summary>A thin-lens camera with the pinhole's placement (see <see cref="StaticCamera(Vector3d, Vector3d, double)"/>); the lens radius is 0 until set.</summary>
  /// <param name="cen">Position of the camera (centre of the lens) in world coordinates.</param>
  /// <param name="dir">Viewing direction; it is normalised.</param>
  /// <param name="ang">Horizontal field of view in degrees.</param>
  public ThinLensCamera(Vector3d cen, Vector3d dir, double ang) : base(cen, dir, ang)
  {
  }

  /// <summary>A thin-lens camera with the given up vector (see <see cref="StaticCamera(Vector3d, Vector3d, Vector3d, double)"/>); the lens radius is 0 until set.</summary>
  /// <param name="cen">Position of the camera (centre of the lens) in world coordinates.</param>
  /// <param name="dir">Viewing direction; it is normalised.</param>
  /// <param name="upv">Up direction, not parallel to <paramref name="dir"/>.</param>
  /// <param name="ang">Horizontal field of view in degrees.</param>
  public ThinLensCamera(Vector3d cen, Vector3d dir, Vector3d upv, double ang) : base(cen, dir, upv, ang)
  {
  }

  /// <summary>A thin-lens camera with its aperture and focus.</summary>
  /// <param name="cen">Position of the camera (centre of the lens) in world coordinates.</param>
  /// <param name="dir">Viewing direction; it is normalised.</param>
  /// <param name="ang">Horizontal field of view in degrees.</param>
  /// <param name="lensRadius">Radius of the lens (<see cref="LensRadius"/>) in world units; 0 is a pinhole.</param>
  /// <param name="focusDistance">Distance of the plane in sharp focus (<see cref="FocusDistance"/>), positive.</param>
  /// <exception cref="ArgumentOutOfRangeException">The radius is negative or the distance is not positive (or either is not finite).</exception>
  public ThinLensCamera(Vector3d cen, Vector3d dir, double ang, double lensRadius, double focusDistance) : base(cen, dir, ang)
  {
    LensRadius = lensRadius;
    FocusDistance = focusDistance;
  }

  /// <summary>Radius of the lens aperture in scene units; 0 = pinhole (everything sharp).</summary>
  public double LensRadius
  {
    get => lensRadius;
    set
    {
      if (!(value >= 0.0) || double.IsInfinity(value))
        throw new ArgumentOutOfRangeException(nameof(value), value, "The lens radius must be 0 (pinhole) or a positive number.");
      lensRadius = value;
    }
  }

  /// <summary>Distance of the plane in sharp focus from the camera, along the viewing direction.</summary>
  public double FocusDistance
  {
    get => focusDistance;
    set
    {
      if (!(value > 0.0) || double.IsInfinity(value))
        throw new ArgumentOutOfRangeException(nameof(value), value, "The focus distance must be a positive number.");
      focusDistance = value;
    }
  }

  /// <summary>Focuses on <paramref name="point"/>: the plane of sharp focus passes through it.</summary>
  public void FocusOn(Vector3d point) => FocusDistance = Vector3d.Dot(point - center, direction.Normalized());

  /// <summary>Recomputes the pinhole's image plane and the lens axes (right and up in the image) and the unit viewing axis.</summary>
  protected override void prepare()
  {
    base.prepare();
    lensRight = dx.Normalized();
    lensUp = -dy.Normalized();
    viewAxis = direction.Normalized();
  }

  /// <summary>
  /// A ray of image point (x, y) through the lens: it starts at a point of the lens disk (the 2D sample of the
  /// current worker's sampler, <see cref="SampleDimension.Lens"/>) and passes through the point where the pinhole ray
  /// meets the plane of sharp focus. With <see cref="LensRadius"/> 0 the pinhole ray. Always true.
  /// </summary>
  /// <param name="x">Horizontal image coordinate in pixels, 0 at the left edge.</param>
  /// <param name="y">Vertical image coordinate in pixels, 0 at the top edge.</param>
  /// <param name="p0">Origin of the ray on the lens (world coordinates).</param>
  /// <param name="p1">Direction of the ray, unit length.</param>
  public override bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1)
  {
    base.GetRay(x, y, out p0, out p1);
    if (lensRadius <= 0.0)
      return true;

    // The pinhole ray meets the focal plane at the point every lens ray of this sample aims at.
    double along = Vector3d.Dot(p1, viewAxis);
    if (along <= 0.0)
      return true;
    Vector3d focus = center + p1 * (focusDistance / along);
    Execution.WorkerContext.Current.Sampler.Get2D(SampleDimension.Lens, out double u, out double v);
    Vector2d lens = SampleWarp.ConcentricDisk(u, v) * lensRadius;
    p0 = center + lensRight * lens.X + lensUp * lens.Y;
    p1 = (focus - p0).Normalized();
    return true;
  }
}
