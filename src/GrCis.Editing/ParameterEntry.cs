namespace GrCis.Editing;

/// <summary>A parameter of a <see cref="SignatureEntry"/>: its text (<c>double kA</c>) and its doc comment.</summary>
public sealed record ParameterEntry(string Label, string? Documentation);
