using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Editing.Tests;

/// <summary>
/// A name of a script cut after its first letters, the rest of the file kept: the text, the caret right after the
/// kept letters, the whole name that completion should offer there, and whether it is a member after a dot.
/// </summary>
internal sealed record CompletionProbe(string File, int Line, string Text, int Caret, string Name, bool IsMember, bool LastOnLine)
{
  /// <summary>
  /// Every name in an expression or a type that binds to a symbol, a member access's name included; not the names a
  /// declaration declares (tokens, not name nodes), <c>using</c> lines, implicit <c>var</c>, nor names of one letter.
  /// A name of two letters is cut after one, a longer one alternately after one and two. Each name gives two probes:
  /// the rest of its line kept, and the rest of its line deleted (the line being typed, the lines below it there).
  /// </summary>
  public static IEnumerable<CompletionProbe> In(string file, string source, SyntaxNode root, SemanticModel model)
  {
    int index = 0;
    foreach (SimpleNameSyntax name in root.DescendantNodes().OfType<SimpleNameSyntax>())
    {
      string text = name.Identifier.ValueText;
      if (text.Length < 2 || name.Identifier.IsMissing || name.Ancestors().Any(a => a is UsingDirectiveSyntax))
        continue;
      if (name is IdentifierNameSyntax { IsVar: true } && model.GetSymbolInfo(name).Symbol is ITypeSymbol { Name: not "var" })
        continue;
      if (model.GetSymbolInfo(name).Symbol is null)
        continue;
      bool member = name.Parent is MemberAccessExpressionSyntax ma && ma.Name == name
                    || name.Parent is QualifiedNameSyntax q && q.Right == name
                    || name.Parent is MemberBindingExpressionSyntax;
      int keep = text.Length == 2 ? 1 : 1 + index++ % 2;
      int start = name.Identifier.SpanStart;
      int end = name.Identifier.Span.End, lineEnd = source.IndexOf('\n', end) is int n and >= 0 ? n : source.Length;
      int line = name.GetLocation().GetLineSpan().StartLinePosition.Line + 1;
      yield return new CompletionProbe(file, line, source[..(start + keep)] + source[end..], start + keep, text, member, false);
      yield return new CompletionProbe(file, line, source[..(start + keep)] + source[lineEnd..], start + keep, text, member, true);
    }
  }

  /// <summary>Whether an entry's label is this name (<c>List&lt;&gt;</c> for <c>List</c>, <c>color:</c> for a named argument).</summary>
  public bool Offered(string label) => label == Name || label == Name + "<>" || label == Name + ":";
}
