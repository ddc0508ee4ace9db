namespace Rendering.Tessellation;

/// <summary>How finely curved solids are cut into triangles, and the image size the camera is set to.</summary>
public sealed record TessellationOptions
{
  /// <summary>Segments around a sphere's axis (longitude steps); default 48 (7.5°).</summary>
  public int SphereSegments { get; init; } = 48;

  /// <summary>Rings from pole to pole (latitude steps); default 24 (7.5°).</summary>
  public int SphereRings { get; init; } = 24;

  /// <summary>Segments around a cylinder's axis; default 48.</summary>
  public int CylinderSegments { get; init; } = 48;

  /// <summary>Segments around a torus's axis; default 48.</summary>
  public int TorusSegments { get; init; } = 48;

  /// <summary>Segments around a torus's tube; default 24.</summary>
  public int TorusTubeSegments { get; init; } = 24;

  /// <summary>Steps along u and along v of each bicubic Bézier patch; default 16.</summary>
  public int BezierSteps { get; init; } = 16;

  /// <summary>Image width in pixels the camera is set to (its aspect ratio); default 640.</summary>
  public int Width { get; init; } = Execution.RenderDefaults.Width;

  /// <summary>Image height in pixels the camera is set to; default 480.</summary>
  public int Height { get; init; } = Execution.RenderDefaults.Height;

  /// <summary>The defaults above.</summary>
  public static TessellationOptions Default { get; } = new();
}
