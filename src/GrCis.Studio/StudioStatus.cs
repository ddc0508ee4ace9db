using System.Collections.Generic;

namespace GrCis.Studio;

/// <summary>The render's state for the page.</summary>
/// <param name="Rendering">The script of the render asked for last is being built, or the render runs.</param>
/// <param name="Diagnostics">The last build's compiler diagnostics (empty when it compiled).</param>
/// <param name="Algorithm">The algorithm chosen for the render (<c>--algorithm</c>'s name); null = the scene's choice.</param>
public sealed record StudioStatus(bool Rendering, int Version, double Fraction, double Seconds, string Statistics, string? Error,
                                  IReadOnlyList<string> Notes, IReadOnlyList<ScriptError> Diagnostics, string? Algorithm = null)
{
  /// <summary>
  /// <c>compiling</c> while a script is built (compiled and run: a render's, or a saved script's that is not the one
  /// rendered), <c>rendering</c> while the pixels are computed, <c>stopping</c> after Stop until the render has ended,
  /// else <c>idle</c>.
  /// </summary>
  public string Phase { get; init; } = "idle";

  /// <summary>The scene whose script <see cref="Diagnostics"/> are in (the render's, or a saved script's that was checked); null when there are none.</summary>
  public string? DiagnosticsScene { get; init; }

  /// <summary>The page (its random id) that started the work on show; null = not known. Another id means another tab took over.</summary>
  public string? Tab { get; init; }

  /// <summary>Passes of samples (true), tiles (false) or by the algorithm (null), as chosen for the render.</summary>
  public bool? Progressive { get; init; }

  /// <summary>Samples per pixel in the image on show during a progressive render, and of the finished image; null = not known.</summary>
  public int? Samples { get; init; }

  /// <summary>The number of the render this status is about: the one asked for last (<see cref="GrCis.Interactive.DemoController.RenderId"/>).</summary>
  public long RenderId { get; init; }

  /// <summary>The size and samples per pixel the last render used (the user's where given, else the script's, else the fields'); null before any.</summary>
  public int? Width { get; init; }

  public int? Height { get; init; }

  public int? SamplesPerPixel { get; init; }

  /// <summary>The estimated RMSE of the image on show (<see cref="Rendering.Execution.NoiseImage"/>); null = no estimate.</summary>
  public double? Noise { get; init; }

  /// <summary>Which studio process answers (<see cref="StudioOptions.Generation"/>): its render numbers start again at 0.</summary>
  public int Generation { get; init; }

  // For the event stream (StudioEvents), not the page: what tells one change from another where values alone may not.

  /// <summary>Counts the changes of <see cref="Error"/> and <see cref="Diagnostics"/> (set or cleared), so the same error twice is news.</summary>
  internal long ErrorSequence { get; init; }

  /// <summary>Counts the completed renders, of which the last was <see cref="CompletedRenderId"/>.</summary>
  internal long Completions { get; init; }

  internal long CompletedRenderId { get; init; }

  /// <summary>The last completed render was stopped before its last pixel.</summary>
  internal bool Cancelled { get; init; }

  /// <summary>The number of the last saved script's check that ran to its end (<see cref="StudioSession.Check"/>); 0 = none.</summary>
  internal long CheckedId { get; init; }
}
