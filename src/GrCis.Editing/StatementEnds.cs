using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Editing;

/// <summary>
/// Where a name being typed at the end of a line is read as the type of a declaration that the next line completes.
/// <c>scene.C</c> above <c>root.InsertChild(s, m);</c> parses as one member, a method <c>scene.C root.InsertChild(s, m)</c>
/// (return type <c>scene.C</c>, <c>root</c> an interface it implements), since a script's top level takes members
/// before statements and white space does not end a statement. In a type's place completion offers types only, none
/// of which is a member of the scene, so the list came out empty.
/// </summary>
internal static class StatementEnds
{
  /// <summary>The end of the word at <paramref name="position"/> when it is such a type, where a <c>;</c> ends its line's statement; else -1.</summary>
  public static int Before(SyntaxNode root, int position)
  {
    if (position == 0)
      return -1;
    SyntaxToken token = root.FindToken(position - 1);
    if (!token.IsKind(Microsoft.CodeAnalysis.CSharp.SyntaxKind.IdentifierToken) || token.SpanStart >= position || token.Span.End < position)
      return -1;
    SyntaxToken next = token.GetNextToken();
    if (next.RawKind == 0 || next.IsKind(Microsoft.CodeAnalysis.CSharp.SyntaxKind.EndOfFileToken))
      return -1;
    SourceText text = root.SyntaxTree.GetText();
    if (text.Lines.IndexOf(next.SpanStart) == text.Lines.IndexOf(token.Span.End))
      return -1; // the next token on the same line: the user wrote them together
    SyntaxNode? type = token.Parent;
    while (type?.Parent is QualifiedNameSyntax or AliasQualifiedNameSyntax)
      type = type.Parent;
    return type?.Parent is VariableDeclarationSyntax or MethodDeclarationSyntax or BasePropertyDeclarationSyntax
      or LocalFunctionStatementSyntax or DeclarationExpressionSyntax or ExplicitInterfaceSpecifierSyntax or IncompleteMemberSyntax
      ? token.Span.End
      : -1;
  }
}
