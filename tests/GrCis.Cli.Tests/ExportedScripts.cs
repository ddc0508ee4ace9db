using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;

namespace GrCis.Cli.Tests;

/// <summary>
/// What the tests of <c>grcis export</c>'s files in other programs share: every script of scripts/ exported as
/// <c>.glb</c>, and the one result line such a program's script prints (<c>GRCIS-RESULT</c> and a JSON array).
/// </summary>
internal static class ExportedScripts
{
  /// <summary>Exports every script of scripts/ into <paramref name="dir"/> (name.glb); returns the files in name order.</summary>
  public static List<string> Glb(TempDirectory dir)
  {
    var files = new List<string>();
    foreach (string script in Directory.GetFiles(RepoPaths.Scripts, "*.cs").Order())
    {
      string name = Path.GetFileNameWithoutExtension(script) + ".glb";
      CliRun run = CliRun.Of(dir.Path, "export", script, "-o", name, "-q");
      Assert.True(run.ExitCode == 0, $"{Path.GetFileName(script)}: {run.Error}");
      files.Add(dir.File(name));
    }
    return files;
  }

  /// <summary>The test's program and script (in tests/GrCis.Cli.Tests/Data), run on <paramref name="files"/>; one report per file, in their order.</summary>
  public static JsonElement[] Reports(string program, IEnumerable<string> arguments, IReadOnlyList<string> files)
  {
    (int code, string output) = Shell.Run(RepoPaths.Root, null, TimeSpan.FromMinutes(5), program, arguments.Concat(files).ToArray());
    const string Marker = "GRCIS-RESULT ";
    string? line = output.Split('\n').FirstOrDefault(l => l.StartsWith(Marker, StringComparison.Ordinal));
    Assert.True(line != null, $"{Path.GetFileName(program)} printed no result (exit {code}):\n{output}");
    JsonElement[] reports = JsonDocument.Parse(line![Marker.Length..]).RootElement.EnumerateArray().ToArray();
    Assert.Equal(files.Select(Path.GetFileName), reports.Select(r => r.GetProperty("file").GetString()));
    return reports;
  }

  /// <summary>A script of tests/GrCis.Cli.Tests/Data.</summary>
  public static string Data(string name) => Path.Combine(RepoPaths.Root, "tests", "GrCis.Cli.Tests", "Data", name);
}
