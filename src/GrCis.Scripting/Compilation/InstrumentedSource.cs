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
  public int ToOriginal(int offset) => SourceMap.ToOriginal(insertions, offset, Original.Length);

  /// <summary>The mapping as plain numbers, for runtime errors after the compilation (and in the compiled-script cache).</summary>
  public SourceMap ToMap()
  {
    static int[] Starts(SourceText text)
    {
      var starts = new int[text.Lines.Count];
      for (int i = 0; i < starts.Length; i++)
        starts[i] = text.Lines[i].Start;
      return starts;
    }
    return new SourceMap(Original.Length, Starts(Original), Instrumented.Length, Starts(Instrumented), insertions);
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
