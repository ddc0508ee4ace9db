namespace Rendering;

/// <summary>How the integrator may reach a light: by sampling it only, or also by a scattered ray that hits it.</summary>
internal enum LightKind
{
  /// <summary>
  /// No ray ever hits it: a point, or one of GrCis's area lights, which have no surface in the scene and give one
  /// point per sample. Only light sampling finds it, so no MIS weight applies.
  /// </summary>
  DeltaPosition,

  /// <summary>An emissive surface of the scene: light sampling and scattered rays both find it (MIS).</summary>
  Area,

  /// <summary>Light arriving from infinitely far (the background): light sampling and rays that leave the scene both find it (MIS).</summary>
  Infinite,
}
