namespace GrCis.Editing;

/// <summary>One entry of a completion list.</summary>
/// <param name="Label">What is inserted (a member, type, keyword or local name).</param>
/// <param name="Kind">Roslyn's tag for the entry, lower case: <c>method</c>, <c>property</c>, <c>field</c>, <c>class</c>, <c>keyword</c> ...</param>
/// <param name="Detail">The signature or type, when the entry was described (the first ones of a list).</param>
/// <param name="Documentation">The summary of its doc comment, when it has one and was described.</param>
public sealed record CompletionEntry(string Label, string Kind, string? Detail, string? Documentation);
