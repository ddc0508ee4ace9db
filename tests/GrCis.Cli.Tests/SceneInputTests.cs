using System;
using System.IO;

namespace GrCis.Cli.Tests;

/// <summary>
/// Input students gave while their scenes were measured: a folder or another file as the scene, a mesh without
/// faces, a mesh file that is not OBJ. Each is named for what it is; an empty mesh renders as nothing.
/// </summary>
public class SceneInputTests
{
  [Theory]
  [InlineData("render")]
  [InlineData("info")]
  [InlineData("animate")]
  public void A_folder_given_as_the_scene_is_named_a_folder_with_what_is_expected(string command)
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("homework"));
    File.WriteAllText(dir.File(Path.Combine("homework", "Scene.cs")), ScriptCommandTests.SceneBody);

    CliRun run = command == "info"
      ? CliRun.Of(dir.Path, command, "homework")
      : CliRun.Of(dir.Path, command, "homework", "-o", "out.png");

    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.Contains("'homework' is a folder, not a scene", line);
    Assert.Contains("built-in scene name", line);
    Assert.Contains("scene script (*.cs)", line);
    Assert.Contains(Path.Combine("homework", "Scene.cs"), line);
    Assert.DoesNotContain("unknown scene", line);
    Assert.False(File.Exists(dir.File("out.png")));
  }

  [Fact]
  public void A_file_that_is_not_a_script_is_named_a_file()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("scene.yaml"), "camera: [0, 0, -5]\n");

    CliRun run = CliRun.Of(dir.Path, "render", "scene.yaml", "-o", "out.png");

    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.Contains("'scene.yaml' is a file but not a scene script", line);
    Assert.DoesNotContain("unknown scene", line);
  }

  [Fact]
  public void A_built_in_name_wins_over_a_folder_of_that_name()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("Cubes"));
    CliRun run = CliRun.Of(dir.Path, "info", "Cubes");
    Assert.Equal(0, run.ExitCode);
  }

  static string MeshScript(TempDirectory dir, string objName) =>
    ScriptCommandTests.SceneBody + $$"""
      SceneBrep brep = new SceneBrep();
      new WavefrontObj().ReadBrep(System.IO.Path.Combine(System.IO.Path.GetDirectoryName((string)context[PropertyName.CTX_SCRIPT_PATH])!, "{{objName}}"), brep);
      root.InsertChild(new TriangleMesh(brep), Matrix4d.Scale(3.0));
      """;

  [Theory]
  [InlineData("none")]
  [InlineData("bvh")]
  public void A_script_with_an_empty_obj_renders_as_without_the_mesh(string accel)
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("empty.obj"), "# exported with no faces\ng nothing\n");
    File.WriteAllText(dir.File("mesh.cs"), MeshScript(dir, "empty.obj"));
    File.WriteAllText(dir.File("plain.cs"), ScriptCommandTests.SceneBody);

    CliRun run = CliRun.Of(dir.Path, "render", "mesh.cs", "--size", "32x24", "--accel", accel, "-o", "mesh.png", "-q");
    Assert.True(run.ExitCode == 0, run.Error);
    CliRun plain = CliRun.Of(dir.Path, "render", "plain.cs", "--size", "32x24", "--accel", accel, "-o", "plain.png", "-q");
    Assert.Equal(0, plain.ExitCode);
    Assert.Equal(File.ReadAllBytes(dir.File("plain.png")), File.ReadAllBytes(dir.File("mesh.png")));
  }

  [Fact]
  public void A_mesh_file_of_random_bytes_is_an_error_naming_the_file_and_no_image_is_written()
  {
    using var dir = new TempDirectory();
    var bytes = new byte[2048];
    new Random(8).NextBytes(bytes);
    File.WriteAllBytes(dir.File("noise.obj"), bytes);
    File.WriteAllText(dir.File("mesh.cs"), MeshScript(dir, "noise.obj"));

    CliRun run = CliRun.Of(dir.Path, "render", "mesh.cs", "--size", "16x12", "-o", "out.png", "-q");

    Assert.NotEqual(0, run.ExitCode);
    string line = Assert.Single(run.ErrorLines);
    Assert.Contains("noise.obj(", line);
    Assert.Contains("not a Wavefront OBJ", line);
    Assert.DoesNotContain("Index was outside", line);
    Assert.False(File.Exists(dir.File("out.png")));
    Assert.DoesNotContain(dir.AllFiles(), f => f.Contains(".tmp"));
  }
}
