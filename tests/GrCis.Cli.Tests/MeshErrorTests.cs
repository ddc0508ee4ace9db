using Scene3D;
using System.IO;
using System.Linq;

namespace GrCis.Cli.Tests;

/// <summary>A malformed OBJ file loaded by a scene script: one line naming the file and line, no image.</summary>
public class MeshErrorTests
{
  [Fact]
  public void Malformed_obj_line_is_reported_with_file_and_line_and_no_image_is_written()
  {
    using var dir = new TempDirectory();
    string obj = dir.File("broken.obj");
    File.WriteAllText(obj, "# a triangle\nv 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n");
    string script = dir.File("mesh.cs");
    File.WriteAllText(script, ScriptCommandTests.SceneBody + """
      SceneBrep brep = new SceneBrep();
      new WavefrontObj().ReadBrep(System.IO.Path.Combine(System.IO.Path.GetDirectoryName((string)context[PropertyName.CTX_SCRIPT_PATH])!, "broken.obj"), brep);
      root.InsertChild(new TriangleMesh(brep), Matrix4d.Identity);
      """);

    CliRun run = CliRun.Of(dir.Path, "render", script, "--size", "16x12", "-o", "out.png", "-q");

    Assert.NotEqual(0, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.Contains("broken.obj(4)", line);
    Assert.False(File.Exists(dir.File("out.png")));
    Assert.DoesNotContain(dir.AllFiles(), f => f.Contains(".tmp"));
  }
}
