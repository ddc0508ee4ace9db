using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Generates primary rays for image points given in pixel units.</summary>
public interface ICamera
{
  /// <summary>Width / height of the image.</summary>
  double AspectRatio { get; set; }

  /// <summary>Width of the image in pixels: <see cref="GetRay"/> takes x in [0, Width].</summary>
  double Width { get; set; }

  /// <summary>Height of the image in pixels: <see cref="GetRay"/> takes y in [0, Height].</summary>
  double Height { get; set; }

  /// <summary>Ray through image point (x, y): <c>p0 + t * p1</c>, t ≥ 0. False when there is no ray.</summary>
  bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1);
}
