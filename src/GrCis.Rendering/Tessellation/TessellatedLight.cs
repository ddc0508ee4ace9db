using OpenTK.Mathematics;

namespace Rendering.Tessellation;

/// <summary>A light of the scene with a place: its kind, centre (world), colour and size.</summary>
public sealed class TessellatedLight
{
  /// <summary>Point, rectangle or sphere.</summary>
  public required TessellatedLightKind Kind { get; init; }

  /// <summary>The light's source object in the scene.</summary>
  public required ILightSource Source { get; init; }

  /// <summary>World position: the point light's position, the rectangle's or sphere's centre.</summary>
  public required Vector3d Position { get; init; }

  /// <summary>The light's intensity per band (RGB), as the scene gives it (GrCis's units: 1 is a plain white light).</summary>
  public required Vector3d Intensity { get; init; }

  /// <summary>A rectangle light's edge vectors (world); zero for the other kinds.</summary>
  public Vector3d EdgeU { get; init; }

  /// <summary>A rectangle light's second edge vector (world); zero for the other kinds.</summary>
  public Vector3d EdgeV { get; init; }

  /// <summary>A sphere light's radius; 0 for the other kinds.</summary>
  public double Radius { get; init; }
}
