using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Wraps every body of user code that can take part in a recursion (methods, local functions, constructors,
/// operators, accessors, lambdas) in <c>var d = Recursion.Enter(); try { … } finally { d.RecursionDepth--; }</c>, so
/// a recursion without end stops with an exception naming its line (<see cref="Rendering.Execution.Recursion"/>)
/// instead of a stack overflow that kills the process. The guard goes on the body's own lines: an expression body
/// <c>=&gt; e;</c> becomes a block in place (<c>=&gt;</c> and <c>;</c> are overwritten, the rest inserted), so no line
/// moves. Async and iterator bodies run in pieces, possibly on other threads, so a count kept across those pieces would
/// be wrong: they begin with a stateless check of the stack left instead (<see cref="Rendering.Execution.Recursion.CheckStack"/>),
/// which ends a recursion through them (an iterator enumerating itself, an async method awaiting itself without ever
/// waiting) before the stack overflows.
/// </summary>
internal static class RecursionGuards
{
  // A local of that name in a nested body shadows the outer one (allowed since C# 8).
  const string Variable = "__grcisCall";
  const string Enter = "var " + Variable + "=global::Rendering.Execution.Recursion.Enter();try{";
  // The decrement inline (a field of the thread's WorkerContext): user code is not optimised, so a call would stay a call.
  const string Exit = "}finally{" + Variable + ".RecursionDepth--;}";
  const string StackCheck = "global::Rendering.Execution.Recursion.CheckStack();";

  /// <summary>The guards of every declared body of <paramref name="tree"/> (parsed from <paramref name="source"/>'s text) added to it.</summary>
  public static InstrumentedSource Instrument(SyntaxTree tree, InstrumentedSource source)
  {
    var edits = new List<(TextSpan Span, string Text)>();
    foreach (SyntaxNode node in tree.GetRoot().DescendantNodes())
    {
      switch (node)
      {
        case MethodDeclarationSyntax m when IsAsync(m.Modifiers):
          GuardAsync(m.Body, m.ExpressionBody, m.SemicolonToken, AsyncReturnsValue(m.ReturnType), edits);
          break;
        case BaseMethodDeclarationSyntax m when !IsAsync(m.Modifiers):
          Guard(m.Body, m.ExpressionBody, m.SemicolonToken, ReturnsValue(m), edits);
          break;
        case LocalFunctionStatementSyntax f when IsAsync(f.Modifiers):
          GuardAsync(f.Body, f.ExpressionBody, f.SemicolonToken, AsyncReturnsValue(f.ReturnType), edits);
          break;
        case LocalFunctionStatementSyntax f when !IsAsync(f.Modifiers):
          Guard(f.Body, f.ExpressionBody, f.SemicolonToken, !IsVoid(f.ReturnType), edits);
          break;
        case AccessorDeclarationSyntax a when !IsAsync(a.Modifiers):
          Guard(a.Body, a.ExpressionBody, a.SemicolonToken, a.Keyword.IsKind(SyntaxKind.GetKeyword), edits);
          break;
        case PropertyDeclarationSyntax { ExpressionBody: { } arrow } p:
          GuardGetter(arrow, p.SemicolonToken, edits);
          break;
        case IndexerDeclarationSyntax { ExpressionBody: { } arrow } i:
          GuardGetter(arrow, i.SemicolonToken, edits);
          break;
        case AnonymousFunctionExpressionSyntax { Block: { } block } l when l.AsyncKeyword.IsKind(SyntaxKind.None):
          GuardBlock(block, edits);
          break;
        case AnonymousFunctionExpressionSyntax { Block: { } block }:
          CheckAtStart(block, edits);
          break;
      }
    }
    return Apply(source, edits);
  }

  /// <summary>
  /// Guards the expression-bodied lambdas that call anything (one without a call cannot recurse). Whether such a body
  /// is a statement or a value depends on the delegate it becomes, so this pass binds; a lambda that becomes an
  /// expression tree keeps its form.
  /// </summary>
  public static CSharpCompilation GuardLambdas(CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                               CSharpParseOptions parseOptions)
  {
    foreach ((SyntaxTree tree, InstrumentedSource source) in sources.ToArray())
    {
      List<AnonymousFunctionExpressionSyntax> lambdas = tree.GetRoot().DescendantNodes().OfType<AnonymousFunctionExpressionSyntax>()
        .Where(l => l.ExpressionBody != null && l.ExpressionBody.DescendantNodesAndSelf().OfType<InvocationExpressionSyntax>().Any())
        .ToList();
      if (lambdas.Count == 0)
        continue;
      SemanticModel model = compilation.GetSemanticModel(tree);
      var edits = new List<(TextSpan Span, string Text, int Owner)>();
      foreach (AnonymousFunctionExpressionSyntax l in lambdas)
      {
        if (model.GetSymbolInfo(l).Symbol is not IMethodSymbol method ||
            model.GetTypeInfo(l).ConvertedType is INamedTypeSymbol { Name: "Expression", ContainingNamespace: var ns } &&
            ns.ToDisplayString() == "System.Linq.Expressions")
          continue;
        ExpressionSyntax body = l.ExpressionBody!;
        bool isAsync = !l.AsyncKeyword.IsKind(SyntaxKind.None);
        // An async lambda's value is its task's result: none for Task, ValueTask or void.
        bool none = method.ReturnsVoid || body is ThrowExpressionSyntax ||
                    isAsync && method.ReturnType is INamedTypeSymbol { Name: "Task" or "ValueTask", IsGenericType: false };
        string value = none ? "" : "return ";
        edits.Add((new TextSpan(body.SpanStart, 0), "{" + (isAsync ? StackCheck : Enter) + value, l.SpanStart));
        edits.Add((new TextSpan(body.Span.End, 0), ";" + (isAsync ? "" : Exit) + "}", l.SpanStart));
      }
      if (edits.Count == 0)
        continue;
      // From the end; where an inner lambda's body ends with the outer one's, the outer close is inserted first and so follows.
      InstrumentedSource edited = source;
      foreach ((TextSpan span, string text, int _) in edits.OrderByDescending(e => e.Span.Start).ThenBy(e => e.Owner))
        edited = edited.WithReplacement(span, text);
      compilation = edited.Replace(tree, compilation, sources, parseOptions);
    }
    return compilation;
  }

  static void Guard(BlockSyntax? body, ArrowExpressionClauseSyntax? arrow, SyntaxToken semicolon, bool returnsValue,
                    List<(TextSpan Span, string Text)> edits)
  {
    if (body != null)
    {
      if (IsIterator(body))
        CheckAtStart(body, edits);
      else
        GuardBlock(body, edits);
    }
    else if (arrow != null && !semicolon.IsMissing)
    {
      string value = returnsValue && arrow.Expression is not ThrowExpressionSyntax ? "return " : "";
      edits.Add((arrow.ArrowToken.Span, "{" + Enter + value));
      edits.Add((semicolon.Span, ";" + Exit + "}"));
    }
  }

  /// <summary>An async body begins with the stack check; an expression body becomes a block in place.</summary>
  static void GuardAsync(BlockSyntax? body, ArrowExpressionClauseSyntax? arrow, SyntaxToken semicolon, bool returnsValue,
                         List<(TextSpan Span, string Text)> edits)
  {
    if (body != null)
      CheckAtStart(body, edits);
    else if (arrow != null && !semicolon.IsMissing)
    {
      string value = returnsValue && arrow.Expression is not ThrowExpressionSyntax ? "return " : "";
      edits.Add((arrow.ArrowToken.Span, "{" + StackCheck + value));
      edits.Add((semicolon.Span, ";}"));
    }
  }

  static void CheckAtStart(BlockSyntax block, List<(TextSpan Span, string Text)> edits)
  {
    if (!block.OpenBraceToken.IsMissing && !block.CloseBraceToken.IsMissing)
      edits.Add((new TextSpan(block.OpenBraceToken.Span.End, 0), StackCheck));
  }

  /// <summary>An async method returns a value unless it is declared <c>void</c>, <c>Task</c> or <c>ValueTask</c>.</summary>
  static bool AsyncReturnsValue(TypeSyntax type)
  {
    SimpleNameSyntax? name = type switch
    {
      QualifiedNameSyntax q => q.Right,
      AliasQualifiedNameSyntax a => a.Name,
      SimpleNameSyntax n => n,
      _ => null,
    };
    return !IsVoid(type) && name is not IdentifierNameSyntax { Identifier.ValueText: "Task" or "ValueTask" };
  }

  /// <summary><c>T P =&gt; e;</c> becomes <c>T P {get{… return e;…}}</c>.</summary>
  static void GuardGetter(ArrowExpressionClauseSyntax arrow, SyntaxToken semicolon, List<(TextSpan Span, string Text)> edits)
  {
    if (semicolon.IsMissing)
      return;
    string value = arrow.Expression is ThrowExpressionSyntax ? "" : "return ";
    edits.Add((arrow.ArrowToken.Span, "{get{" + Enter + value));
    edits.Add((semicolon.Span, ";" + Exit + "}}"));
  }

  static void GuardBlock(BlockSyntax block, List<(TextSpan Span, string Text)> edits)
  {
    if (block.OpenBraceToken.IsMissing || block.CloseBraceToken.IsMissing)
      return;
    int open = block.OpenBraceToken.Span.End, close = block.CloseBraceToken.SpanStart;
    if (open == close)
      edits.Add((new TextSpan(open, 0), Enter + Exit));
    else
    {
      edits.Add((new TextSpan(open, 0), Enter));
      edits.Add((new TextSpan(close, 0), Exit));
    }
  }

  static InstrumentedSource Apply(InstrumentedSource source, List<(TextSpan Span, string Text)> edits)
  {
    // From the end, so earlier positions stay valid (no two edits share a position).
    InstrumentedSource edited = source;
    foreach ((TextSpan span, string text) in edits.OrderByDescending(e => e.Span.Start))
      edited = edited.WithReplacement(span, text);
    return edited;
  }

  static bool ReturnsValue(BaseMethodDeclarationSyntax m) => m switch
  {
    MethodDeclarationSyntax method => !IsVoid(method.ReturnType),
    OperatorDeclarationSyntax or ConversionOperatorDeclarationSyntax => true,
    _ => false, // constructors, destructors
  };

  static bool IsVoid(TypeSyntax type) => type is PredefinedTypeSyntax p && p.Keyword.IsKind(SyntaxKind.VoidKeyword);

  static bool IsAsync(SyntaxTokenList modifiers) => modifiers.Any(SyntaxKind.AsyncKeyword);

  /// <summary>A body with <c>yield</c> of its own (not of a function inside it).</summary>
  static bool IsIterator(BlockSyntax body) =>
    body.DescendantNodes(n => n == body || n is not (AnonymousFunctionExpressionSyntax or LocalFunctionStatementSyntax))
        .Any(n => n is YieldStatementSyntax);
}
