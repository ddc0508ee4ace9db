using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.Json;
using GrCis.TestSupport;
using SharpGLTF.Schema2;

namespace GrCis.Cli.Tests;

/// <summary>
/// Blender (Debian's 3.4, run as <c>blender -b</c> with its own glTF importer) imports every script's
/// <c>grcis export</c> and makes of each file a mesh object per solid node, the camera and every light the file holds.
/// </summary>
public class BlenderImportTests
{
  [SkippableFact]
  public void Blender_imports_every_scripts_export_with_its_solids_camera_and_lights()
  {
    string blender = RequiredTool.Find("blender", "blender python3-numpy");
    using var dir = new TempDirectory();
    var files = new List<string>();
    foreach (string script in Directory.GetFiles(RepoPaths.Scripts, "*.cs").Order())
    {
      string name = Path.GetFileNameWithoutExtension(script) + ".glb";
      CliRun run = CliRun.Of(dir.Path, "export", script, "-o", name, "-q");
      Assert.True(run.ExitCode == 0, $"{Path.GetFileName(script)}: {run.Error}");
      files.Add(dir.File(name));
    }

    var start = new ProcessStartInfo(blender) { RedirectStandardOutput = true, RedirectStandardError = true };
    foreach (string a in new[] { "-b", "--factory-startup", "--python", Path.Combine(RepoPaths.Root, "tests", "GrCis.Cli.Tests", "Data", "import-gltf.py"), "--" })
      start.ArgumentList.Add(a);
    foreach (string f in files)
      start.ArgumentList.Add(f);
    using Process p = Process.Start(start)!;
    var error = p.StandardError.ReadToEndAsync();
    string output = p.StandardOutput.ReadToEnd();
    Assert.True(p.WaitForExit(TimeSpan.FromMinutes(5)), "Blender did not finish within 5 minutes");
    string? line = output.Split('\n').FirstOrDefault(l => l.StartsWith("GRCIS-RESULT ", StringComparison.Ordinal));
    Assert.True(line != null, $"Blender printed no result (exit {p.ExitCode}):\n{output}\n{error.Result}");

    JsonElement[] reports = JsonDocument.Parse(line!["GRCIS-RESULT ".Length..]).RootElement.EnumerateArray().ToArray();
    Assert.Equal(files.Select(Path.GetFileName), reports.Select(r => r.GetProperty("file").GetString()));
    foreach ((string file, JsonElement report) in files.Zip(reports))
    {
      ModelRoot model = ModelRoot.Load(file);
      string what = Path.GetFileName(file);
      Assert.True(model.LogicalNodes.Count(n => n.Mesh != null) == report.GetProperty("meshes").GetInt32(), $"{what}: mesh objects");
      Assert.True(report.GetProperty("cameras").GetInt32() == 1, $"{what}: cameras");
      Assert.True(model.LogicalNodes.Count(n => n.PunctualLight != null) == report.GetProperty("lights").GetInt32(), $"{what}: lights");
    }
  }
}
