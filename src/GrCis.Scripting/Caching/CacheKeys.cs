using System;
using System.Collections.Generic;
using System.Security.Cryptography;
using System.Text;
using GrCis.Scripting.Compilation;

namespace GrCis.Scripting.Caching;

/// <summary>
/// Keys of the compiled-script cache: a SHA-256 over everything a compilation depends on. For a script, its full
/// path (messages and the PDB name it) and text, and the keys of the modules it references; for a module, every
/// <c>*.cs</c> file of its folders by folder, path and text, and the keys of the modules compiled before it. For both, the library:
/// the entry format, the runtime's version, and the MVIDs of System.Private.CoreLib and of the
/// <see cref="LibraryAssemblies"/>. These are deterministic builds, so an MVID changes exactly when the assembly
/// does: GrCis.Scripting's covers the compiler passes (interruption points, override access, data-file calls,
/// shadowed library types ...), the compiler options and the Roslyn version it references; and whether scripts
/// are optimised.
/// </summary>
internal static class CacheKeys
{
  static readonly Lazy<string> library = new(LibraryIdentity);

  /// <summary>What every key starts with: the entry format, the runtime and the library assemblies.</summary>
  public static string Library => library.Value;

  public static string Script(string path, string source, IReadOnlyList<ScriptModule> modules, bool optimize) =>
    Script(Library, path, source, modules, optimize);

  /// <param name="library">The library's identity (<see cref="Library"/>).</param>
  public static string Script(string library, string path, string source, IReadOnlyList<ScriptModule> modules, bool optimize)
  {
    var text = new StringBuilder(source.Length + 512);
    text.Append("script\0").Append(library).Append('\0').Append(Options(optimize)).Append('\0').Append(path).Append('\0');
    foreach (ScriptModule m in modules)
      text.Append(m.CacheKey).Append('\0');
    text.Append(source);
    return Hash(text.ToString());
  }

  /// <summary>What module folders hold: each folder's <c>*.cs</c> files, scene scripts among them (which of them are is decided by their text), by path and content.</summary>
  public static string ModuleContent(IReadOnlyList<ModuleFiles.Candidate> candidates)
  {
    var text = new StringBuilder();
    foreach (ModuleFiles.Candidate c in candidates)
      text.Append(c.Directory).Append('\0').Append(c.File).Append('\0').Append(c.Text.Length).Append('\0').Append(c.Text).Append('\0');
    return Hash(text.ToString());
  }

  /// <param name="content">The folders' <see cref="ModuleContent"/>.</param>
  /// <param name="earlier">The modules compiled before it, which it references.</param>
  public static string Module(string content, IReadOnlyList<ScriptModule> earlier, bool optimize)
  {
    var text = new StringBuilder();
    text.Append("module\0").Append(Library).Append('\0').Append(Options(optimize)).Append('\0').Append(content).Append('\0');
    foreach (ScriptModule m in earlier)
      text.Append(m.CacheKey).Append('\0');
    return Hash(text.ToString());
  }

  static string Options(bool optimize) => optimize ? "optimize" : "debug";

  static string LibraryIdentity()
  {
    var text = new StringBuilder();
    text.Append("format ").Append(CacheEntries.FormatVersion).Append("; runtime ").Append(Environment.Version);
    text.Append("; ").Append(typeof(object).Assembly.ManifestModule.ModuleVersionId);
    foreach (System.Reflection.Assembly a in LibraryAssemblies.All)
      text.Append("; ").Append(a.GetName().Name).Append(' ').Append(a.ManifestModule.ModuleVersionId);
    return text.ToString();
  }

  static string Hash(string text) => Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(text))).ToLowerInvariant();
}
