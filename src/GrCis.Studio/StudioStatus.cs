using System.Collections.Generic;

namespace GrCis.Studio;

/// <summary>The render's state for the page.</summary>
public sealed record StudioStatus(bool Rendering, int Version, double Fraction, double Seconds, string Statistics, string? Error,
                                  IReadOnlyList<string> Notes);
