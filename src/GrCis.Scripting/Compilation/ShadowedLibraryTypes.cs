using System;
using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// A student's module may declare a type that GrCis itself added later under the same full name (a
/// <c>Rendering.AnimatedCamera</c> written in May 2020, a week before GrCis got its own). Inside the module
/// the student's type wins (a source type beats a referenced one), but a script sees both and C# refuses the
/// name (CS0433), and <c>extern alias</c> does not exist in scripts. So such a type is compiled under a
/// suffixed name (<see cref="Suffix"/>; every reference to it in the module follows, positions mapped back),
/// and scripts get a <c>using</c> alias of the plain name for it: the student's class wins, as in its year.
/// </summary>
internal static class ShadowedLibraryTypes
{
  public const string Suffix = "__module";

  /// <summary>A module type renamed: where it is declared (1-based line and column), its full name, and the alias scripts get.</summary>
  public sealed record Renamed(string Path, int Line, int Column, string FullName)
  {
    public string Name => FullName[(FullName.LastIndexOf('.') + 1)..];

    /// <summary>The alias that gives scripts the module's type under its plain name.</summary>
    public string Alias => $"using {Name} = global::{FullName}{Suffix}; ";
  }

  /// <summary>
  /// Renames the top-level public non-generic types of the module that a GrCis library assembly also declares.
  /// A <c>partial</c> one meant to add members to the library's class (as a student's project, which compiled
  /// GrCis's sources in, could): that cannot work across assemblies, so it is not renamed but explained in
  /// <paramref name="partials"/>, an error to show when the module does not compile.
  /// </summary>
  public static CSharpCompilation Rename(CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                         CSharpParseOptions parseOptions, List<Renamed> renamed, List<ScriptDiagnostic> partials)
  {
    List<IAssemblySymbol> libraries = compilation.References
      .Select(compilation.GetAssemblyOrModuleSymbol).OfType<IAssemblySymbol>()
      .Where(a => a.Name.StartsWith("GrCis.", StringComparison.Ordinal)).ToList();
    var clashing = new HashSet<INamedTypeSymbol>(SymbolEqualityComparer.Default);
    foreach ((SyntaxTree tree, InstrumentedSource source) in sources)
    {
      SemanticModel model = compilation.GetSemanticModel(tree);
      foreach (BaseTypeDeclarationSyntax declaration in tree.GetRoot().DescendantNodes().OfType<BaseTypeDeclarationSyntax>())
      {
        if (model.GetDeclaredSymbol(declaration) is not INamedTypeSymbol { ContainingType: null, IsGenericType: false, DeclaredAccessibility: Accessibility.Public } type)
          continue;
        string fullName = type.ToDisplayString(SymbolDisplayFormat.FullyQualifiedFormat).Replace("global::", "", StringComparison.Ordinal);
        if (!libraries.Any(a => a.GetTypeByMetadataName(fullName) is { DeclaredAccessibility: Accessibility.Public }) || !clashing.Add(type))
          continue;
        LinePosition at = source.Original.Lines.GetLinePosition(source.ToOriginal(declaration.Identifier.SpanStart));
        if (type.DeclaringSyntaxReferences.Length > 1 || declaration.Modifiers.Any(SyntaxKind.PartialKeyword))
        {
          clashing.Remove(type);
          partials.Add(new ScriptDiagnostic(tree.FilePath, at.Line + 1, at.Character + 1, "error", ScriptDiagnostic.PartialLibraryTypeId,
            $"'partial' '{fullName}' adds to a class of the library, which a module cannot do (the library is compiled apart); " +
            "put the new members in a class of the module's own (a subclass, or a static class of helpers)"));
          continue;
        }
        renamed.Add(new Renamed(tree.FilePath, at.Line + 1, at.Character + 1, fullName));
      }
    }
    if (clashing.Count == 0)
      return compilation;

    // Find every reference with the original compilation first: once one file is renamed, the others would bind to the library's type.
    var names = new HashSet<string>(clashing.Select(t => t.Name), StringComparer.Ordinal);
    var edits = new List<(SyntaxTree Tree, InstrumentedSource Source, List<int> Ends)>();
    foreach ((SyntaxTree tree, InstrumentedSource source) in sources)
    {
      SemanticModel model = compilation.GetSemanticModel(tree);
      var ends = new List<int>();
      foreach (SyntaxToken token in tree.GetRoot().DescendantTokens())
      {
        if (!token.IsKind(SyntaxKind.IdentifierToken) || !names.Contains(token.ValueText))
          continue;
        ISymbol? symbol = token.Parent switch
        {
          BaseTypeDeclarationSyntax d when d.Identifier == token => model.GetDeclaredSymbol(d),
          ConstructorDeclarationSyntax c => model.GetDeclaredSymbol(c)?.ContainingType,
          DestructorDeclarationSyntax c => model.GetDeclaredSymbol(c)?.ContainingType,
          SimpleNameSyntax n => Target(model.GetSymbolInfo(n)),
          _ => null,
        };
        if (symbol is INamedTypeSymbol named && clashing.Contains(named.OriginalDefinition))
          ends.Add(token.Span.End);
      }
      if (ends.Count > 0)
        edits.Add((tree, source, ends));
    }
    foreach ((SyntaxTree tree, InstrumentedSource source, List<int> ends) in edits)
    {
      InstrumentedSource edited = source;
      foreach (int end in ends.OrderByDescending(e => e))
        edited = edited.WithReplacement(new TextSpan(end, 0), Suffix);
      compilation = edited.Replace(tree, compilation, sources, parseOptions);
    }
    return compilation;
  }

  /// <summary>One warning per renamed type.</summary>
  public static IEnumerable<ScriptDiagnostic> Report(IEnumerable<Renamed> renamed) =>
    renamed.Select(r => new ScriptDiagnostic(r.Path, r.Line, r.Column, "warning", ScriptDiagnostic.ShadowedLibraryTypeId,
      $"'{r.FullName}' is also a type of the library (GrCis added it later); the module and its scripts use this one"));

  /// <summary>
  /// The script text with the aliases of <paramref name="modules"/>' renamed types inserted at the start of its
  /// first line that is not a directive (no line moves).
  /// </summary>
  public static InstrumentedSource WithAliases(InstrumentedSource script, IReadOnlyList<ScriptModule> modules)
  {
    string aliases = string.Concat(modules.SelectMany(m => m.Renamed).Select(r => r.Alias));
    if (aliases.Length == 0)
      return script;
    int at = 0;
    foreach (TextLine line in script.Instrumented.Lines)
    {
      if (!line.ToString().TrimStart().StartsWith('#'))
      {
        at = line.Start;
        break;
      }
    }
    return script.WithReplacement(new TextSpan(at, 0), aliases);
  }

  static ISymbol? Target(SymbolInfo info)
  {
    ISymbol? s = info.Symbol ?? info.CandidateSymbols.FirstOrDefault();
    return s is IMethodSymbol { MethodKind: MethodKind.Constructor } m ? m.ContainingType : s;
  }
}
