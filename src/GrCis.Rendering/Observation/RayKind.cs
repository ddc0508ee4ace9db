namespace Rendering.Observation;

/// <summary>Why a ray was traced.</summary>
public enum RayKind
{
  /// <summary>From the camera.</summary>
  Primary,

  /// <summary>From a hit towards a light, to test visibility.</summary>
  Shadow,

  /// <summary>Mirrored about the normal at the parent hit.</summary>
  Reflected,

  /// <summary>Bent through the surface at the parent hit.</summary>
  Refracted,

  /// <summary>Asked for by a solid's own recursion function (<see cref="Rendering.RecursionFunction"/>) or a subclass.</summary>
  Secondary,
}
