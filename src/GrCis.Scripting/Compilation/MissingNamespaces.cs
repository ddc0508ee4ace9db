using System;
using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// GrCis-era code names platform namespaces (System, Microsoft, OpenTK) .NET 10 does not have (<c>System.Windows.Forms</c> in a module copied
/// from the demo project, <c>OpenTK.Graphics</c>, <c>System.Runtime.Remoting</c>). A <c>using</c> of such
/// a namespace is blanked out (spaces, so no position moves) and reported: a warning when nothing needed
/// it, an error saying what is gone and what to use instead when the code still fails to compile.
/// </summary>
internal static class MissingNamespaces
{
  /// <summary>A using to blank out: its span in the compiled text and what it named.</summary>
  public sealed record Missing(TextSpan Span, string Namespace);

  /// <summary>A using that was blanked out: where it is in the user's file and what it named.</summary>
  public sealed record Removed(string Path, LinePosition At, string Namespace);

  static readonly string[] platformRoots = { "System", "Microsoft", "OpenTK" };

  static readonly (string Prefix, string Hint)[] hints =
  {
    ("System.Windows.Forms", "WinForms is not available to scripts and modules here (they run in the command line and in the demo on every OS); keep window code out of scene code"),
    ("System.Drawing", "System.Drawing's bitmaps are not referenced; read images with Rendering.Imaging.ImageFile and write them with FloatImage/Rgb8Image"),
    ("OpenTK.Graphics", "only OpenTK's math types are here (namespace OpenTK.Mathematics); OpenGL is not available to scene code"),
    ("OpenTK.Input", "only OpenTK's math types are here (namespace OpenTK.Mathematics)"),
    ("OpenTK.Platform", "only OpenTK's math types are here (namespace OpenTK.Mathematics)"),
    ("System.Runtime.Remoting", ".NET Remoting was removed from .NET; scene code does not need it"),
  };

  /// <summary>The usings of <paramref name="tree"/> that name nothing <paramref name="compilation"/> knows.</summary>
  public static List<Missing> Find(CSharpCompilation compilation, SyntaxTree tree)
  {
    var missing = new List<Missing>();
    SemanticModel? model = null;
    foreach (UsingDirectiveSyntax u in tree.GetRoot().DescendantNodes().OfType<UsingDirectiveSyntax>())
    {
      // `using static` and aliases are left to the compiler's own messages.
      if (u.StaticKeyword.IsKind(SyntaxKind.StaticKeyword) || u.Alias != null || u.NamespaceOrType is not NameSyntax name)
        continue;
      // Only platform namespaces: a missing namespace of the user's own usually means a forgotten --module.
      string ns = name.ToString();
      if (!platformRoots.Any(root => ns == root || ns.StartsWith(root + ".", StringComparison.Ordinal)))
        continue;
      model ??= compilation.GetSemanticModel(tree);
      SymbolInfo info = model.GetSymbolInfo(name);
      if (info.Symbol == null && info.CandidateSymbols.IsEmpty)
        missing.Add(new Missing(u.Span, ns));
    }
    return missing;
  }

  /// <summary>The text with each missing using replaced by spaces of the same length.</summary>
  public static SourceText Blank(SourceText text, IEnumerable<Missing> missing) =>
    text.WithChanges(missing.Select(m => new TextChange(m.Span, new string(' ', m.Span.Length))));

  public static string Hint(string ns)
  {
    foreach ((string prefix, string hint) in hints)
      if (ns == prefix || ns.StartsWith(prefix + ".", StringComparison.Ordinal))
        return hint;
    return "it is not part of .NET 10";
  }

  /// <summary>One diagnostic per removed using: a warning when the code compiled without it, else an error.</summary>
  public static IEnumerable<ScriptDiagnostic> Report(IEnumerable<Removed> removed, bool compiled)
  {
    foreach (Removed r in removed)
    {
      yield return compiled
        ? new ScriptDiagnostic(r.Path, r.At.Line + 1, r.At.Character + 1, "warning", ScriptDiagnostic.MissingNamespaceId,
            $"'using {r.Namespace};' was ignored: the namespace does not exist here ({Hint(r.Namespace)}); nothing in the file needed it")
        : new ScriptDiagnostic(r.Path, r.At.Line + 1, r.At.Character + 1, "error", ScriptDiagnostic.MissingNamespaceId,
            $"namespace '{r.Namespace}' does not exist here: {Hint(r.Namespace)}; the errors below about names the file expected from it follow from that");
    }
  }
}
