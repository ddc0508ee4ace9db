using System.Collections.Generic;
using System.Linq;
using System.Text;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Inserts a call to <see cref="Rendering.Execution.Interruption.Poll"/> into every loop body and before
/// every <c>goto</c> of user code, so a host can stop a script stuck in an endless loop (.NET cannot
/// abort a thread). Each such statement <c>S</c> becomes <c>{Poll();S}</c>, on the same line: no line
/// moves, and <see cref="InstrumentedSource"/> maps columns back.
/// </summary>
internal static class InterruptionPoints
{
  const string Poll = "global::Rendering.Execution.Interruption.Poll();";
  const string Open = "{" + Poll;
  const string Close = "}";

  public static InstrumentedSource Instrument(SyntaxTree tree)
  {
    SourceText original = tree.GetText();
    // At one position closing braces come first: "S1;S2;" with both wrapped is "{P;S1;}{P;S2;}".
    var closes = new Dictionary<int, int>();
    var opens = new Dictionary<int, int>();
    foreach (StatementSyntax s in Targets(tree.GetRoot()))
    {
      opens[s.SpanStart] = opens.GetValueOrDefault(s.SpanStart) + 1;
      closes[s.Span.End] = closes.GetValueOrDefault(s.Span.End) + 1;
    }
    if (opens.Count == 0)
      return new InstrumentedSource(original, original, []);

    var changes = new List<TextChange>();
    var insertions = new List<(int, int)>();
    foreach (int position in opens.Keys.Concat(closes.Keys).Distinct().Order())
    {
      var text = new StringBuilder();
      text.Insert(0, Close, closes.GetValueOrDefault(position));
      text.Insert(text.Length, Open, opens.GetValueOrDefault(position));
      changes.Add(new TextChange(new TextSpan(position, 0), text.ToString()));
      insertions.Add((position, text.Length));
    }
    return new InstrumentedSource(original, original.WithChanges(changes), insertions.ToArray());
  }

  /// <summary>Loop bodies and goto statements: the places a program can go round for ever without a call.</summary>
  static IEnumerable<StatementSyntax> Targets(SyntaxNode root)
  {
    foreach (SyntaxNode node in root.DescendantNodes())
    {
      switch (node)
      {
        case WhileStatementSyntax w:
          yield return w.Statement;
          break;
        case DoStatementSyntax d:
          yield return d.Statement;
          break;
        case ForStatementSyntax f:
          yield return f.Statement;
          break;
        case CommonForEachStatementSyntax fe:
          yield return fe.Statement;
          break;
        case GotoStatementSyntax g:
          yield return g;
          break;
      }
    }
  }
}
