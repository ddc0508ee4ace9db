using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Threading;
using GrCis.Scripting;
using Microsoft.CodeAnalysis;

namespace GrCis.Editing;

/// <summary>
/// The references scripts compile against, each with its XML documentation where the machine has it: the
/// GrCis assemblies' own files (built beside them) and the framework's from the SDK's reference pack. The
/// runtime's implementation assembly (System.Private.CoreLib) has no file of its own; its public types are
/// documented in the reference pack under their contract assemblies, so it reads those.
/// </summary>
internal static class DocumentedReferences
{
  // The contract assemblies whose types System.Private.CoreLib implements and scripts use most.
  static readonly string[] CoreLibContracts = { "System.Runtime", "System.Collections", "System.Console", "System.Runtime.Intrinsics" };

  /// <summary>What a script compiles against (<see cref="ScriptCompilationInputs"/>), the modules' with their own doc comments.</summary>
  public static IReadOnlyList<MetadataReference> For(IReadOnlyList<ScriptModule> modules) =>
    With(ScriptCompilationInputs.FrameworkReferences).Concat(modules.Select(Documented)).ToList();

  static MetadataReference Documented(ScriptModule module)
  {
    byte[] xml = ScriptCompilationInputs.ModuleDocumentation(module);
    return ScriptCompilationInputs.ModuleReference(module, xml.Length > 0 ? XmlDocumentationProvider.CreateFromBytes(xml) : null);
  }

  public static IReadOnlyList<MetadataReference> With(IEnumerable<MetadataReference> references)
  {
    string? packDir = ReferencePackDirectory();
    var result = new List<MetadataReference>();
    foreach (MetadataReference r in references)
    {
      if (r is not PortableExecutableReference { FilePath: { } path } pe)
      {
        result.Add(r);
        continue;
      }
      string name = Path.GetFileNameWithoutExtension(path);
      DocumentationProvider? docs = null;
      string beside = Path.ChangeExtension(path, ".xml");
      if (File.Exists(beside))
        docs = XmlDocumentationProvider.CreateFromFile(beside);
      else if (packDir is not null && name == "System.Private.CoreLib")
        docs = new FirstOf(CoreLibContracts.Select(c => Path.Combine(packDir, c + ".xml")).Where(File.Exists).ToArray());
      else if (packDir is not null && File.Exists(Path.Combine(packDir, name + ".xml")))
        docs = XmlDocumentationProvider.CreateFromFile(Path.Combine(packDir, name + ".xml"));
      result.Add(docs is null ? pe : MetadataReference.CreateFromFile(path, pe.Properties, docs));
    }
    return result;
  }

  /// <summary><c>packs/Microsoft.NETCore.App.Ref/&lt;version&gt;/ref/net&lt;major&gt;.0</c> of the running runtime's SDK, if installed.</summary>
  static string? ReferencePackDirectory()
  {
    // <root>/shared/Microsoft.NETCore.App/<version>/System.Private.CoreLib.dll
    string runtimeDir = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
    string? root = Path.GetDirectoryName(Path.GetDirectoryName(Path.GetDirectoryName(runtimeDir)));
    if (root is null)
      return null;
    string packs = Path.Combine(root, "packs", "Microsoft.NETCore.App.Ref");
    if (!Directory.Exists(packs))
      return null;
    int major = Environment.Version.Major;
    string tfm = $"net{major}.0";
    return Directory.EnumerateDirectories(packs)
      .Where(d => Version.TryParse(Path.GetFileName(d).Split('-')[0], out Version? v) && v.Major == major)
      .OrderByDescending(d => Version.Parse(Path.GetFileName(d).Split('-')[0]))
      .Select(d => Path.Combine(d, "ref", tfm))
      .FirstOrDefault(Directory.Exists);
  }

  /// <summary>
  /// The members of several documentation files, indexed when first asked for: each member's element is found by a plain
  /// text scan and kept as its place in the file's text, cut out when a symbol's documentation is asked for. (Parsing the
  /// 13 MB of these files into a tree took seconds of the editor's first completion of a framework member.)
  /// </summary>
  sealed class FirstOf(string[] files) : DocumentationProvider
  {
    readonly Lazy<Dictionary<string, Member>> members = new(() => Index(files));

    readonly record struct Member(string Text, int Start, int Length);

    protected override string? GetDocumentationForSymbol(string documentationMemberID, CultureInfo preferredCulture, CancellationToken cancellationToken = default) =>
      members.Value.TryGetValue(documentationMemberID, out Member m) ? m.Text.Substring(m.Start, m.Length) : null;

    static Dictionary<string, Member> Index(string[] files)
    {
      const string Open = "<member name=\"";
      var all = new Dictionary<string, Member>(StringComparer.Ordinal);
      foreach (string file in files)
      {
        string text = File.ReadAllText(file);
        int at = text.IndexOf(Open, StringComparison.Ordinal);
        while (at >= 0)
        {
          int nameEnd = text.IndexOf('"', at + Open.Length);
          int tagEnd = nameEnd < 0 ? -1 : text.IndexOf('>', nameEnd);
          if (tagEnd < 0)
            break;
          // <member name="…"/> holds nothing; otherwise the element ends at its closing tag (members do not nest).
          int end = text[tagEnd - 1] == '/' ? tagEnd + 1 : text.IndexOf("</member>", tagEnd, StringComparison.Ordinal) is int close and >= 0 ? close + "</member>".Length : -1;
          if (end < 0)
            break;
          all.TryAdd(text.Substring(at + Open.Length, nameEnd - at - Open.Length), new Member(text, at, end - at));
          at = text.IndexOf(Open, end, StringComparison.Ordinal);
        }
      }
      return all;
    }

    public override bool Equals(object? obj) => ReferenceEquals(this, obj);

    public override int GetHashCode() => System.Runtime.CompilerServices.RuntimeHelpers.GetHashCode(this);
  }
}
