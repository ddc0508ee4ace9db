namespace GrCis.Editing;

/// <summary>What hovering a name shows: its declaration and its doc comment.</summary>
/// <param name="From">Start of the hovered name (character offset).</param>
/// <param name="To">End of the hovered name.</param>
/// <param name="Text">The declaration as Roslyn's quick info gives it, e.g. <c>class Rendering.PhongMaterial</c>.</param>
/// <param name="Documentation">The doc comment's summary (and remarks on the parameters), if any.</param>
public sealed record HoverInfo(int From, int To, string Text, string? Documentation);
