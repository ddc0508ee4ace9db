using System;
using System.Collections.Generic;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// A user's source file with interruption points inserted (see <see cref="InterruptionPoints"/>), and the
/// way back: compiler diagnostics and stack-trace columns refer to the instrumented text, the user must
/// see positions in the file as written. Insertions hold no line break, so lines never move.
/// </summary>
internal sealed class InstrumentedSource
{
  readonly (int Position, int Length)[] insertions;

  public InstrumentedSource(SourceText original, SourceText instrumented, (int Position, int Length)[] insertions)
  {
    Original = original;
    Instrumented = instrumented;
    this.insertions = insertions;
  }

  public SourceText Original { get; }

  /// <summary>The same mapping over <paramref name="text"/>, an edit of <see cref="Instrumented"/> that moves no character (blanked spans).</summary>
  public InstrumentedSource WithInstrumented(SourceText text) =>
    text.Length == Instrumented.Length ? new InstrumentedSource(Original, text, insertions)
      : throw new ArgumentException("The edited text must keep every position.", nameof(text));

  public SourceText Instrumented { get; }

  /// <summary>
  /// The same mapping over <see cref="Instrumented"/> with <paramref name="span"/> replaced by
  /// <paramref name="text"/>: a shorter text is padded with spaces, the characters of a longer one beyond the
  /// span count as inserted there, so every other position still maps to the user's file.
  /// </summary>
  public InstrumentedSource WithReplacement(TextSpan span, string text)
  {
    if (text.Length <= span.Length)
      return WithInstrumented(Instrumented.WithChanges(new TextChange(span, text.PadRight(span.Length))));
    int at = ToOriginal(span.End);
    int extra = text.Length - span.Length;
    var merged = new System.Collections.Generic.List<(int Position, int Length)>(insertions.Length + 1);
    bool added = false;
    foreach ((int position, int length) in insertions)
    {
      if (!added && position > at)
      {
        merged.Add((at, extra));
        added = true;
      }
      merged.Add((position, length));
    }
    if (!added)
      merged.Add((at, extra));
    return new InstrumentedSource(Original, Instrumented.WithChanges(new TextChange(span, text)), merged.ToArray());
  }

  /// <summary>The offset in the original text of an offset in the instrumented one (inside an insertion: where it was inserted).</summary>
  public int ToOriginal(int offset)
  {
    int shift = 0;
    foreach ((int position, int length) in insertions)
    {
      int start = position + shift;
      if (offset < start)
        break;
      if (offset < start + length)
        return position;
      shift += length;
    }
    return Math.Clamp(offset - shift, 0, Original.Length);
  }

  /// <summary>0-based line and character in the original text of a 0-based position in the instrumented one.</summary>
  public LinePosition ToOriginal(LinePosition position)
  {
    if (position.Line >= Instrumented.Lines.Count)
      return position;
    TextLine line = Instrumented.Lines[position.Line];
    int offset = Math.Min(line.Start + position.Character, line.EndIncludingLineBreak);
    return Original.Lines.GetLinePosition(ToOriginal(offset));
  }

  /// <summary>1-based column in the original text of a 1-based line and column of the instrumented one (0 = unknown stays 0).</summary>
  public int OriginalColumn(int line, int column)
  {
    if (line <= 0 || column <= 0)
      return column;
    return ToOriginal(new LinePosition(line - 1, column - 1)).Character + 1;
  }

  /// <summary>
  /// Puts this source (an edit of <paramref name="tree"/>'s) in the place of <paramref name="tree"/>: parsed with
  /// <paramref name="parseOptions"/>, in <paramref name="compilation"/> and in the <paramref name="sources"/> of a pass.
  /// </summary>
  public CSharpCompilation Replace(SyntaxTree tree, CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                   CSharpParseOptions parseOptions)
  {
    SyntaxTree rewritten = CSharpSyntaxTree.ParseText(Instrumented, parseOptions, tree.FilePath);
    sources.Remove(tree);
    sources[rewritten] = this;
    return compilation.ReplaceSyntaxTree(tree, rewritten);
  }
}
