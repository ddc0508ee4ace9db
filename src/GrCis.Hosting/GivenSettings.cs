using System;

namespace GrCis.Hosting;

/// <summary>
/// The settings a user gave explicitly, which win over a scene script's choices (<see cref="Precedence"/>).
/// <c>grcis</c> marks the options typed on the command line; the demo marks its ray-tracing switches (as
/// GrCis's window, whose check boxes apply to a script's ray tracer) and leaves size and sampling to the script.
/// </summary>
[Flags]
public enum GivenSettings
{
  None = 0,
  Size = 1,
  SamplesPerPixel = 2,
  Jitter = 4,
  Shadows = 8,
  Reflections = 16,
  Refractions = 32,
  Accel = 64,
  Gamma = 128,
  Time = 256,
  Algorithm = 512,

  /// <summary>The three ray-tracing switches.</summary>
  Switches = Shadows | Reflections | Refractions,

  /// <summary>Options only the library's own renderer honours.</summary>
  Sampling = SamplesPerPixel | Jitter,
}
