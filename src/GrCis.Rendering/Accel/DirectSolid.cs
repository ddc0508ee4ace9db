namespace Rendering.Accel;

/// <summary>
/// A library solid whose record kernel and hit set-up the prepared scene calls by name rather than through
/// <see cref="IRecordSolid"/>: decided once per member when the scene is prepared (<see cref="LibraryTypes.DirectKernel"/>).
/// Code compiled without a profile (ReadyToRun, a render's first moments) then makes no interface call per ray.
/// </summary>
internal enum DirectSolid : byte
{
  /// <summary>Any other solid, called through its interface.</summary>
  None,

  /// <summary>Exactly the library's <see cref="Rendering.Sphere"/>.</summary>
  Sphere,

  /// <summary>Exactly the library's <see cref="Rendering.Plane"/>.</summary>
  Plane,

  /// <summary>A solid whose shadow queries use its any-hit walk (<see cref="IAnyHitSolid"/>, the library's mesh); its records through its interface.</summary>
  AnyHit,
}
