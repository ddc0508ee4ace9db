using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text;

namespace GrCis.Cli.Scaffolding;

/// <summary>
/// The files of a scene script folder (templates/grcis-scene in the repository, embedded in the CLI; the
/// template package GrCis.Templates packs the same folder). Applies what <c>dotnet new grcis-scene</c> applies:
/// the folder's name in place of <see cref="SourceName"/> in file names, the packages' version in place of
/// <see cref="VersionToken"/>.
/// </summary>
internal static class SceneFolderTemplate
{
  /// <summary>The project's name in the template (template.json's sourceName).</summary>
  public const string SourceName = "GrCisScene";

  /// <summary>Stands for the version of the GrCis packages the project references.</summary>
  public const string VersionToken = "GRCIS_VERSION";

  const string ResourcePrefix = "grcis-scene/";

  /// <summary>The version of this grcis, which is the version of the packages built with it (Directory.Build.props).</summary>
  public static string PackageVersion
  {
    get
    {
      string v = typeof(SceneFolderTemplate).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion
        ?? typeof(SceneFolderTemplate).Assembly.GetName().Version!.ToString(3);
      // Source link appends "+commit".
      int plus = v.IndexOf('+', StringComparison.Ordinal);
      return plus >= 0 ? v[..plus] : v;
    }
  }

  /// <summary>The files for a project named <paramref name="name"/>: relative path ('/'-separated) and content.</summary>
  public static IReadOnlyList<(string Path, string Text)> Files(string name)
  {
    Assembly assembly = typeof(SceneFolderTemplate).Assembly;
    var files = new List<(string, string)>();
    foreach (string resource in assembly.GetManifestResourceNames().Where(r => r.StartsWith(ResourcePrefix, StringComparison.Ordinal)).Order(StringComparer.Ordinal))
    {
      using Stream stream = assembly.GetManifestResourceStream(resource)!;
      using var reader = new StreamReader(stream, Encoding.UTF8);
      string relative = resource[ResourcePrefix.Length..].Replace('\\', '/');
      files.Add((relative.Replace(SourceName, name, StringComparison.Ordinal), reader.ReadToEnd().Replace(VersionToken, PackageVersion, StringComparison.Ordinal)));
    }
    if (files.Count == 0)
      throw new InvalidOperationException("the scene template is not embedded in grcis (resources grcis-scene/*)");
    return files;
  }
}
