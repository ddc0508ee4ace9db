namespace GrCis.Studio;

/// <summary>One compiler diagnostic of a scene script, for the editor to mark at its line and column (1-based).</summary>
public sealed record ScriptError(int Line, int Column, string Severity, string Id, string Message);
