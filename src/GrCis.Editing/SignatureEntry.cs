using System.Collections.Generic;

namespace GrCis.Editing;

/// <summary>One overload shown by signature help.</summary>
/// <param name="Label">The whole signature, e.g. <c>Sphere()</c> or <c>PhongMaterial(double[] color, double kA, ...)</c>.</param>
/// <param name="Documentation">The summary of the member's doc comment, if any.</param>
/// <param name="Parameters">Each parameter's text (type and name) and its doc comment, in order.</param>
public sealed record SignatureEntry(string Label, string? Documentation, IReadOnlyList<ParameterEntry> Parameters);
