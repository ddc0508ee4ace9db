using System.Collections.Generic;
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
    List<string> files = ExportedScripts.Glb(dir);
    JsonElement[] reports = ExportedScripts.Reports(blender, ["-b", "--factory-startup", "--python", ExportedScripts.Data("import-gltf.py"), "--"], files);
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
