using System;
using System.Collections.Generic;
using System.IO;
using Microsoft.CodeAnalysis;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Metadata references every script and module compiles against: the shared framework and the
/// <see cref="LibraryAssemblies"/>. Created once per process: Roslyn keys its metadata cache by reference object,
/// so sharing them keeps repeated compilations from reloading ~170 assemblies' metadata.
/// </summary>
internal static class FrameworkReferences
{
  static readonly Lazy<IReadOnlyList<MetadataReference>> all = new(Create);

  public static IReadOnlyList<MetadataReference> All => all.Value;

  static IReadOnlyList<MetadataReference> Create()
  {
    var list = new List<MetadataReference>();
    var seen = new HashSet<string>(StringComparer.OrdinalIgnoreCase);

    // The shared framework: every managed assembly beside System.Private.CoreLib.
    string frameworkDir = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
    foreach (string file in Directory.EnumerateFiles(frameworkDir, "*.dll"))
    {
      string name = Path.GetFileNameWithoutExtension(file);
      if (name.StartsWith("Microsoft.VisualBasic", StringComparison.OrdinalIgnoreCase) || !IsManaged(file))
        continue;
      if (seen.Add(name))
        list.Add(MetadataReference.CreateFromFile(file));
    }

    foreach (System.Reflection.Assembly a in LibraryAssemblies.All)
      if (seen.Add(a.GetName().Name!))
        list.Add(MetadataReference.CreateFromFile(a.Location));

    return list;
  }

  static bool IsManaged(string file)
  {
    try
    {
      using var stream = File.OpenRead(file);
      using var pe = new System.Reflection.PortableExecutable.PEReader(stream);
      return pe.HasMetadata;
    }
    catch (BadImageFormatException)
    {
      return false;
    }
  }
}
