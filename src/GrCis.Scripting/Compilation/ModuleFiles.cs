using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Which files of a module folder are module code. Students keep their scene scripts (top-level
/// statements in GrCis's script dialect) beside their classes, and a copied project folder holds
/// build output; GrCis never compiled either as part of the program, so neither is compiled here.
/// </summary>
internal static class ModuleFiles
{
  /// <summary>A <c>*.cs</c> file found in a module folder, with its text (read once: for the cache key, then to compile).</summary>
  public sealed record Candidate(string Directory, string File, string Text);

  /// <summary>Build output and tool folders of a C# project (generated AssemblyInfo files would clash).</summary>
  static readonly string[] skippedFolders = { "bin", "obj", ".git", ".vs", ".idea", "node_modules" };

  /// <summary>A module file's text, parsed once: to tell scene scripts apart and then to compile.</summary>
  public static SyntaxTree Parse(string path, string source) =>
    CSharpSyntaxTree.ParseText(SourceText.From(source, Encoding.UTF8), ScriptCompiler.ModuleParseOptions, path);

  /// <summary>Every <c>*.cs</c> below <paramref name="directory"/> outside build-output folders, in ordinal order.</summary>
  public static string[] Candidates(string directory)
  {
    var files = new List<string>();
    foreach (string file in Directory.EnumerateFiles(directory, "*.cs", SearchOption.AllDirectories))
    {
      string relative = Path.GetRelativePath(directory, file);
      string[] parts = relative.Split(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar);
      if (!parts[..^1].Any(p => skippedFolders.Contains(p, StringComparer.OrdinalIgnoreCase)))
        files.Add(file);
    }
    files.Sort(StringComparer.Ordinal);
    return files.ToArray();
  }

  /// <summary>
  /// True for a scene script: statements at the top level (GrCis's script dialect, or a program
  /// with top-level statements), which a library of classes cannot hold.
  /// </summary>
  public static bool IsSceneScript(SyntaxTree tree) =>
    ((CompilationUnitSyntax)tree.GetRoot()).Members.Any(m => m is GlobalStatementSyntax);
}
