using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Editing;

/// <summary>
/// The type the code around the caret asks of the expression being typed (a typed variable's initializer, an
/// assignment's right side, a condition, the type after <c>new</c> in a typed declaration), and whether an entry
/// gives that type: such entries come first among equally good matches. <c>Dictionary&lt;string, string&gt; p =
/// Util.P</c> means <c>ParseKeyValueList</c>, not <c>ParseDoubleList</c>; <c>if (p.T</c> a method returning
/// <c>bool</c>. Where nothing asks for a type (or only <c>object</c>), nothing fits and the order is as before.
/// </summary>
internal sealed class TargetTyping
{
  readonly SemanticModel? model;
  readonly int position;
  readonly ITypeSymbol? expected;
  readonly INamespaceOrTypeSymbol? container; // after a dot: the type or namespace whose members are offered
  readonly bool created;                      // the name is the type of a `new` expression

  TargetTyping(SemanticModel? model, int position, ITypeSymbol? expected, INamespaceOrTypeSymbol? container, bool created)
  {
    this.model = model;
    this.position = position;
    this.expected = expected;
    this.container = container;
    this.created = created;
  }

  static readonly TargetTyping None = new(null, 0, null, null, false);

  /// <summary>Whether anything asks for a type here (else <see cref="Fits"/> is always false).</summary>
  public bool Asks => expected is not null;

  public static TargetTyping At(SemanticModel? model, SyntaxNode root, int position)
  {
    if (model is null)
      return None;
    SyntaxToken word = position > 0 ? root.FindToken(position - 1) : default;
    SyntaxNode? node;
    if (word.IsKind(SyntaxKind.IdentifierToken) && word.Span.End >= position)
      node = word.Parent;
    else if (word.IsKind(SyntaxKind.DotToken) && word.Span.End == position && word.Parent is MemberAccessExpressionSyntax or QualifiedNameSyntax)
      node = word.Parent; // nothing typed after the dot yet
    else
      return None;
    INamespaceOrTypeSymbol? container = null;
    switch (node)
    {
      case SimpleNameSyntax name when name.Parent is MemberAccessExpressionSyntax access && access.Name == name:
        node = access;
        break;
      case SimpleNameSyntax name when name.Parent is QualifiedNameSyntax qualified && qualified.Right == name:
        node = qualified;
        break;
    }
    if (node is MemberAccessExpressionSyntax member)
      container = model.GetSymbolInfo(member.Expression).Symbol as INamespaceOrTypeSymbol ?? model.GetTypeInfo(member.Expression).Type;
    else if (node is QualifiedNameSyntax qualifiedName)
      container = model.GetSymbolInfo(qualifiedName.Left).Symbol as INamespaceOrTypeSymbol;
    if (node?.Parent is InvocationExpressionSyntax call && call.Expression == node)
      node = call;
    bool created = false;
    if (node?.Parent is ObjectCreationExpressionSyntax creation && creation.Type == node)
    {
      node = creation;
      created = true;
    }
    ITypeSymbol? expected = node is null ? null : Expected(model, node);
    if (expected is null || expected.TypeKind == TypeKind.Error || expected.SpecialType == SpecialType.System_Object)
      return None;
    return new TargetTyping(model, position, expected, container, created);
  }

  // What the parent of the expression asks of it, where the code says so plainly.
  static ITypeSymbol? Expected(SemanticModel model, SyntaxNode node)
  {
    ITypeSymbol Bool() => model.Compilation.GetSpecialType(SpecialType.System_Boolean);
    return node.Parent switch
    {
      EqualsValueClauseSyntax { Parent: VariableDeclaratorSyntax { Parent: VariableDeclarationSyntax declaration } } when !declaration.Type.IsVar =>
        model.GetTypeInfo(declaration.Type).Type,
      AssignmentExpressionSyntax assignment when assignment.Right == node && assignment.IsKind(SyntaxKind.SimpleAssignmentExpression) =>
        model.GetTypeInfo(assignment.Left).Type,
      IfStatementSyntax s when s.Condition == node => Bool(),
      WhileStatementSyntax s when s.Condition == node => Bool(),
      DoStatementSyntax s when s.Condition == node => Bool(),
      ForStatementSyntax s when s.Condition == node => Bool(),
      ConditionalExpressionSyntax c when c.Condition == node => Bool(),
      PrefixUnaryExpressionSyntax u when u.IsKind(SyntaxKind.LogicalNotExpression) => Bool(),
      BinaryExpressionSyntax b when b.IsKind(SyntaxKind.LogicalAndExpression) || b.IsKind(SyntaxKind.LogicalOrExpression) => Bool(),
      _ => null,
    };
  }

  /// <summary>Whether a symbol of this name here (a member of what precedes the dot, if any) gives the asked type.</summary>
  public bool Fits(string name)
  {
    if (expected is null)
      return false;
    foreach (ISymbol symbol in model!.LookupSymbols(position, container, name, includeReducedExtensionMethods: true))
    {
      ITypeSymbol? type = symbol switch
      {
        INamedTypeSymbol t when created => t,
        _ when created => null,
        IMethodSymbol m => m.ReturnType,
        IPropertySymbol p => p.Type,
        IFieldSymbol f => f.Type,
        ILocalSymbol l => l.Type,
        IParameterSymbol p => p.Type,
        _ => null,
      };
      if (type is not null && type.TypeKind != TypeKind.Error && model.Compilation.ClassifyCommonConversion(type, expected).IsImplicit)
        return true;
    }
    return false;
  }
}
