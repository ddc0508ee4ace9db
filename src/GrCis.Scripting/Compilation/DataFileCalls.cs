using System;
using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Students read their own data files (a camera path, a YAML scene, a table) with .NET's file API, by paths
/// written for GrCis on Windows: <c>\</c> separators, any letter case, relative to the project's
/// <c>bin/Debug</c>. The library's loaders find such files through <see cref="Utilities.DataFiles"/>; here the
/// path argument of the reading calls in scripts and modules (<c>File.ReadAllText</c> and the other
/// <c>File</c> reads, <c>File.Exists</c>, <c>new StreamReader(path)</c>) is wrapped in
/// <c>DataFiles.ResolveOrKeep(…)</c> at compile time, on the same line, so they find them too. Writes are
/// left alone: a file to be created is named as the user wrote it.
/// </summary>
internal static class DataFileCalls
{
  const string Open = "global::Utilities.DataFiles.ResolveOrKeep(";

  static readonly HashSet<string> fileReads = new(StringComparer.Ordinal)
  {
    "ReadAllText", "ReadAllLines", "ReadAllBytes", "ReadLines", "OpenRead", "OpenText", "Exists",
    "ReadAllTextAsync", "ReadAllLinesAsync", "ReadAllBytesAsync", "ReadLinesAsync",
  };

  /// <summary>Rewrites the path arguments of reading calls in every user tree of <paramref name="compilation"/>.</summary>
  public static CSharpCompilation Rewrite(CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                          CSharpParseOptions parseOptions)
  {
    foreach ((SyntaxTree tree, InstrumentedSource source) in sources.ToArray())
    {
      // Binding is the costly part: only files that name the API at all.
      string text = source.Instrumented.ToString();
      if (!text.Contains("StreamReader", StringComparison.Ordinal) && !text.Contains("File.", StringComparison.Ordinal))
        continue;
      SemanticModel model = compilation.GetSemanticModel(tree);
      var paths = new List<TextSpan>();
      foreach (SyntaxNode node in tree.GetRoot().DescendantNodes())
      {
        (ArgumentListSyntax? arguments, ExpressionSyntax? call) = node switch
        {
          BaseObjectCreationExpressionSyntax c => (c.ArgumentList, (ExpressionSyntax)c),
          InvocationExpressionSyntax i => (i.ArgumentList, i),
          _ => (null, null),
        };
        if (arguments == null || arguments.Arguments.Count == 0 || model.GetSymbolInfo(call!).Symbol is not IMethodSymbol method ||
            !ReadsAFile(method) || PathArgument(arguments, method.Parameters[0].Name) is not ArgumentSyntax path)
          continue;
        paths.Add(path.Expression.Span);
      }
      if (paths.Count == 0)
        continue;

      // Insert from the end, so earlier positions stay valid; the inserted text maps back to the user's line.
      var inserts = paths.SelectMany(p => new[] { (At: p.End, Text: ")"), (At: p.Start, Text: Open) })
                         .OrderByDescending(i => i.At).ThenBy(i => i.Text == Open ? 1 : 0);
      InstrumentedSource edited = source;
      foreach ((int at, string insert) in inserts)
        edited = edited.WithReplacement(new TextSpan(at, 0), insert);
      compilation = edited.Replace(tree, compilation, sources, parseOptions);
    }
    return compilation;
  }

  /// <summary><c>File</c>'s reading methods and <c>StreamReader</c>'s constructors, when their first parameter is a path.</summary>
  static bool ReadsAFile(IMethodSymbol method)
  {
    if (method.Parameters.Length == 0 || method.Parameters[0].Type.SpecialType != SpecialType.System_String)
      return false;
    string type = method.ContainingType.ToDisplayString();
    return method.MethodKind == MethodKind.Constructor ? type == "System.IO.StreamReader"
      : type == "System.IO.File" && fileReads.Contains(method.Name);
  }

  /// <summary>The argument bound to the parameter named <paramref name="parameter"/>: named, or the first positional one.</summary>
  static ArgumentSyntax? PathArgument(ArgumentListSyntax arguments, string parameter)
  {
    foreach (ArgumentSyntax a in arguments.Arguments)
      if (a.NameColon?.Name.Identifier.Text == parameter)
        return a;
    ArgumentSyntax first = arguments.Arguments[0];
    return first.NameColon == null ? first : null;
  }
}
