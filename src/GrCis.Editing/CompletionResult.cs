using System.Collections.Generic;

namespace GrCis.Editing;

/// <summary>A completion list for a position: the entries and the span of the source they replace.</summary>
/// <param name="From">Start of the replaced span (the partly typed word), a character offset.</param>
/// <param name="To">End of the replaced span.</param>
/// <param name="Items">Entries matching the typed word, best first (at most <see cref="ScriptAssistant.MaxCompletions"/>).</param>
public sealed record CompletionResult(int From, int To, IReadOnlyList<CompletionEntry> Items);
