using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// GrCis changed the access of members students override (<c>RayTracing.shade</c> was <c>protected</c> until
/// 2021 and is <c>public</c> now), and a student keeps the form of the year they forked. C# requires an
/// override to repeat the overridden member's access exactly (CS0507), so such an override is given the
/// library's access at compile time, in place, and reported as a warning at its line: the code means the
/// same member either way.
/// </summary>
internal static class OverrideAccess
{
  /// <summary>An override whose access was changed: where it is in the user's file, and from what to what.</summary>
  public sealed record Changed(string Path, LinePosition At, string Member, string From, string To);

  /// <summary>Rewrites the access of every override that differs from its base member's (CS0507); records each in <paramref name="changed"/>.</summary>
  public static CSharpCompilation Normalize(CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                            CSharpParseOptions parseOptions, List<Changed> changed)
  {
    // Declaration diagnostics are cheap to ask for (no method bodies are bound) and nearly always empty.
    List<Diagnostic> found = compilation.GetDeclarationDiagnostics().Where(d => d.Id == "CS0507" && d.Location.SourceTree != null).ToList();
    foreach (IGrouping<SyntaxTree, Diagnostic> inTree in found.GroupBy(d => d.Location.SourceTree!))
    {
      SyntaxTree tree = inTree.Key;
      if (!sources.TryGetValue(tree, out InstrumentedSource? source))
        continue;
      SemanticModel model = compilation.GetSemanticModel(tree);
      var edits = new List<(TextSpan Span, string Text, Changed What)>();
      foreach (Diagnostic d in inTree)
      {
        MemberDeclarationSyntax? member = tree.GetRoot().FindNode(d.Location.SourceSpan)
          .AncestorsAndSelf().OfType<MemberDeclarationSyntax>().FirstOrDefault();
        if (member == null || edits.Any(e => e.Span.IntersectsWith(member.Modifiers.Span)))
          continue;
        ISymbol? overridden = model.GetDeclaredSymbol(member) switch
        {
          IMethodSymbol m => m.OverriddenMethod,
          IPropertySymbol p => p.OverriddenProperty,
          IEventSymbol e => e.OverriddenEvent,
          _ => null,
        };
        if (overridden == null)
          continue;
        string access = Keywords(overridden, compilation.Assembly);
        SyntaxToken[] tokens = member.Modifiers.Where(IsAccess).ToArray();
        string written = tokens.Length == 0 ? "private" : string.Join(" ", tokens.Select(t => t.Text));
        // No access keyword (private by default): the new one goes before the first modifier.
        TextSpan span = tokens.Length == 0 ? new TextSpan(member.Modifiers.Span.Start, 0)
                                           : TextSpan.FromBounds(tokens[0].SpanStart, tokens[^1].Span.End);
        string text = tokens.Length == 0 ? access + " " : access;
        LinePosition at = source.Original.Lines.GetLinePosition(source.ToOriginal(member.Modifiers.Span.Start));
        edits.Add((span, text, new Changed(tree.FilePath, at, overridden.ContainingType.Name + "." + overridden.Name, written, access)));
      }
      if (edits.Count == 0)
        continue;

      // Apply from the end so earlier spans keep their positions.
      InstrumentedSource edited = source;
      foreach ((TextSpan span, string text, Changed _) in edits.OrderByDescending(e => e.Span.Start))
        edited = edited.WithReplacement(span, text);
      compilation = edited.Replace(tree, compilation, sources, parseOptions);
      changed.AddRange(edits.Select(e => e.What));
    }
    return compilation;
  }

  /// <summary>One warning per changed override.</summary>
  public static IEnumerable<ScriptDiagnostic> Report(IEnumerable<Changed> changed) =>
    changed.Select(c => new ScriptDiagnostic(c.Path, c.At.Line + 1, c.At.Character + 1, "warning", ScriptDiagnostic.OverrideAccessId,
      $"'{c.Member}' is {c.To} here (GrCis changed its access over the years); this override's '{c.From}' is read as '{c.To}'"));

  static bool IsAccess(SyntaxToken t) =>
    t.IsKind(SyntaxKind.PublicKeyword) || t.IsKind(SyntaxKind.ProtectedKeyword) ||
    t.IsKind(SyntaxKind.InternalKeyword) || t.IsKind(SyntaxKind.PrivateKeyword);

  /// <summary>The access keywords an override of <paramref name="member"/> declared in <paramref name="overriding"/> must use.</summary>
  static string Keywords(ISymbol member, IAssemblySymbol overriding) => member.DeclaredAccessibility switch
  {
    Accessibility.Public => "public",
    Accessibility.Internal => "internal",
    Accessibility.Private => "private",
    // Across assemblies a protected internal member is overridden as protected.
    Accessibility.ProtectedOrInternal => SymbolEqualityComparer.Default.Equals(member.ContainingAssembly, overriding) ? "protected internal" : "protected",
    Accessibility.ProtectedAndInternal => "private protected",
    _ => "protected",
  };
}
