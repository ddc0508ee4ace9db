using OpenTK.Mathematics;

namespace Rendering.Tessellation;

/// <summary>The scene's camera as a pinhole: where it is, where it looks, which way is up and how much it sees.</summary>
public sealed class TessellatedCamera
{
  /// <summary>Position (world): where the primary rays start.</summary>
  public required Vector3d Position { get; init; }

  /// <summary>Unit direction of the ray through the image centre.</summary>
  public required Vector3d Direction { get; init; }

  /// <summary>Unit vector towards the image's top edge, perpendicular to <see cref="Direction"/>.</summary>
  public required Vector3d Up { get; init; }

  /// <summary>Vertical field of view in radians (top edge to bottom edge through the centre).</summary>
  public required double VerticalFov { get; init; }

  /// <summary>Width / height of the image.</summary>
  public required double AspectRatio { get; init; }

  /// <summary>
  /// True for a <see cref="StaticCamera"/> (and its library subclasses): the values are the camera's own. False for a
  /// script's camera, whose values are measured from its rays at the image centre and edges (it may not be a pinhole).
  /// </summary>
  public bool Exact { get; init; }
}
