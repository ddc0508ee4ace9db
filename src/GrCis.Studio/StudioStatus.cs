using System.Collections.Generic;

namespace GrCis.Studio;

/// <summary>The render's state for the page.</summary>
/// <param name="Rendering">A script is being built or a render runs.</param>
/// <param name="Diagnostics">The last build's compiler diagnostics (empty when it compiled).</param>
/// <param name="Algorithm">The algorithm chosen for the render (<c>--algorithm</c>'s name); null = the scene's choice.</param>
public sealed record StudioStatus(bool Rendering, int Version, double Fraction, double Seconds, string Statistics, string? Error,
                                  IReadOnlyList<string> Notes, IReadOnlyList<ScriptError> Diagnostics, string? Algorithm = null);
