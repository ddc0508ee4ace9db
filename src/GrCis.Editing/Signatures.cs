using System.Collections.Generic;
using System.Collections.Immutable;
using System.Linq;
using System.Threading;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Editing;

/// <summary>
/// Signature help from the semantic model (Roslyn keeps its own provider internal): the innermost argument
/// list around the caret, the overloads its call or <c>new</c> may mean, and the argument the caret is in.
/// </summary>
internal static class Signatures
{
  static readonly SymbolDisplayFormat Format = SymbolDisplayFormat.MinimallyQualifiedFormat
    .WithParameterOptions(SymbolDisplayParameterOptions.IncludeType | SymbolDisplayParameterOptions.IncludeName |
                          SymbolDisplayParameterOptions.IncludeParamsRefOut | SymbolDisplayParameterOptions.IncludeDefaultValue)
    .WithMemberOptions(SymbolDisplayMemberOptions.IncludeParameters | SymbolDisplayMemberOptions.IncludeContainingType |
                       SymbolDisplayMemberOptions.IncludeType);

  public static SignatureHelp? At(SyntaxNode root, SemanticModel model, int position, CancellationToken cancel)
  {
    SyntaxToken token = root.FindToken(position > 0 ? position - 1 : 0);
    for (SyntaxNode? node = token.Parent; node is not null; node = node.Parent)
    {
      if (node is not BaseArgumentListSyntax args || !Inside(args, position))
        continue;
      ImmutableArray<IMethodSymbol> overloads = Overloads(args.Parent, model, cancel);
      if (overloads.IsEmpty)
        return null;
      int active = args.Arguments.GetSeparators().Count(c => c.SpanStart < position);
      IMethodSymbol? bound = args.Parent is null ? null : model.GetSymbolInfo(args.Parent, cancel).Symbol as IMethodSymbol;
      int chosen = bound is not null ? overloads.IndexOf(bound, SymbolEqualityComparer.Default) : -1;
      if (chosen < 0)
        chosen = Fitting(overloads, args, active, model);
      return new SignatureHelp(overloads.Select(Entry).ToList(), chosen, active);
    }
    return null;
  }

  // Between the parentheses (or brackets), the closing one excluded; an unclosed list runs to its end.
  static bool Inside(BaseArgumentListSyntax args, int position)
  {
    SyntaxToken open = args is ArgumentListSyntax a ? a.OpenParenToken : ((BracketedArgumentListSyntax)args).OpenBracketToken;
    SyntaxToken close = args is ArgumentListSyntax b ? b.CloseParenToken : ((BracketedArgumentListSyntax)args).CloseBracketToken;
    return position > open.SpanStart && (close.IsMissing || position <= close.SpanStart);
  }

  static ImmutableArray<IMethodSymbol> Overloads(SyntaxNode? call, SemanticModel model, CancellationToken cancel)
  {
    IEnumerable<ISymbol> candidates = call switch
    {
      InvocationExpressionSyntax invocation => model.GetMemberGroup(invocation.Expression, cancel),
      BaseObjectCreationExpressionSyntax creation => (model.GetTypeInfo(creation, cancel).Type as INamedTypeSymbol)?.InstanceConstructors
                                                     ?? Enumerable.Empty<ISymbol>(),
      ConstructorInitializerSyntax initializer => model.GetMemberGroup(initializer, cancel),
      _ => Enumerable.Empty<ISymbol>(),
    };
    return candidates.OfType<IMethodSymbol>()
      .Where(m => call is null || model.IsAccessible(call.SpanStart, m))
      .OrderBy(m => m.Parameters.Length)
      .ToImmutableArray();
  }

  // The first overload with room for the caret's argument and every argument written (after the caret too, where a
  // call is being edited) that takes each of them as written: new PhongMaterial(|new double[] {...}, 0.1) is not the
  // copy constructor though it is the first with one parameter.
  static int Fitting(ImmutableArray<IMethodSymbol> overloads, BaseArgumentListSyntax args, int active, SemanticModel model)
  {
    int written = args.Arguments.Count(a => !a.Expression.IsMissing) == 0 ? 0 : args.Arguments.Count;
    int roomy = -1, roomyForAll = -1;
    for (int i = 0; i < overloads.Length; i++)
    {
      ImmutableArray<IParameterSymbol> parameters = overloads[i].Parameters;
      bool isParams = parameters.LastOrDefault()?.IsParams == true;
      if (parameters.Length <= active && !isParams)
        continue;
      if (roomy < 0)
        roomy = i;
      if (parameters.Length < written && !isParams)
        continue;
      if (roomyForAll < 0)
        roomyForAll = i;
      bool fits = true;
      for (int a = 0; a < args.Arguments.Count && fits; a++)
      {
        ExpressionSyntax argument = args.Arguments[a].Expression;
        if (argument.IsMissing || model.GetTypeInfo(argument).Type is { TypeKind: TypeKind.Error })
          continue; // an argument still being typed (new Vec) says nothing yet
        IParameterSymbol p = parameters[System.Math.Min(a, parameters.Length - 1)];
        ITypeSymbol type = p.IsParams && a >= parameters.Length - 1 && p.Type is IArrayTypeSymbol array ? array.ElementType : p.Type;
        fits = model.ClassifyConversion(argument, type).IsImplicit;
      }
      if (fits)
        return i;
    }
    return roomyForAll >= 0 ? roomyForAll : roomy < 0 ? 0 : roomy;
  }

  /// <summary>How signature help shows <paramref name="method"/>: <c>PhongMaterial(double[] color, ...)</c>, <c>Matrix4d.CreateTranslation(double x, ...)</c>.</summary>
  public static string Label(IMethodSymbol method) =>
    method.MethodKind == MethodKind.Constructor
      ? method.ContainingType.Name + "(" + string.Join(", ", method.Parameters.Select(p => p.ToDisplayString(Format))) + ")"
      : method.ToDisplayString(Format);

  static SignatureEntry Entry(IMethodSymbol method)
  {
    string label = Label(method);
    return new SignatureEntry(label, DocComments.Summary(method),
      method.Parameters.Select(p => new ParameterEntry(p.ToDisplayString(Format), DocComments.Parameter(p))).ToList());
  }
}
