using System;
using System.IO;
using System.Linq;
using GrCis.Cli.Scaffolding;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis init [DIR]</c> writes the scene template's folder (templates/grcis-scene, the files of
/// <c>dotnet new grcis-scene</c>), never replaces a file, and its script renders as written.
/// </summary>
public class InitCommandTests
{
  static string TemplateFolder => Path.Combine(RepoPaths.Root, "templates", "grcis-scene");

  [Fact]
  public void Init_writes_the_template_folder_with_the_project_named_after_the_folder()
  {
    using var tmp = new TempDirectory();
    CliRun run = CliRun.Of(tmp.Path, "init", "MyScene");

    Assert.True(run.ExitCode == 0, run.Error);
    string folder = tmp.File("MyScene");
    // Every file of the template except the template engine's own settings, with the same content but the version.
    string[] expected = Directory.GetFiles(TemplateFolder, "*", SearchOption.AllDirectories)
      .Select(f => Path.GetRelativePath(TemplateFolder, f).Replace('\\', '/'))
      .Where(f => !f.StartsWith(".template.config/", StringComparison.Ordinal) && !f.StartsWith("bin/", StringComparison.Ordinal) && !f.StartsWith("obj/", StringComparison.Ordinal))
      .Order(StringComparer.Ordinal).ToArray();
    string[] written = Directory.GetFiles(folder, "*", SearchOption.AllDirectories)
      .Select(f => Path.GetRelativePath(folder, f).Replace('\\', '/')).Order(StringComparer.Ordinal).ToArray();
    Assert.Equal(expected.Select(f => f.Replace(SceneFolderTemplate.SourceName, "MyScene", StringComparison.Ordinal)).Order(StringComparer.Ordinal), written);
    foreach (string f in expected)
    {
      string text = File.ReadAllText(Path.Combine(TemplateFolder, f));
      string actual = File.ReadAllText(Path.Combine(folder, f.Replace(SceneFolderTemplate.SourceName, "MyScene", StringComparison.Ordinal)));
      Assert.Equal(text.Replace(SceneFolderTemplate.VersionToken, SceneFolderTemplate.PackageVersion, StringComparison.Ordinal), actual);
    }
    // The project references the packages of this very build.
    string project = File.ReadAllText(Path.Combine(folder, "MyScene.csproj"));
    Assert.Contains($"Include=\"GrCis.Rendering\" Version=\"{SceneFolderTemplate.PackageVersion}\"", project, StringComparison.Ordinal);
    Assert.DoesNotContain(SceneFolderTemplate.VersionToken, project, StringComparison.Ordinal);
    Assert.Contains("created MyScene/Scene.cs".Replace('/', Path.DirectorySeparatorChar), run.Out, StringComparison.Ordinal);
  }

  [Fact]
  public void Template_content_never_names_the_project_so_init_and_dotnet_new_agree()
  {
    // dotnet new replaces the sourceName in content too; init only in file names. Nothing to replace keeps them equal.
    foreach (string f in Directory.GetFiles(TemplateFolder, "*", SearchOption.AllDirectories).Where(f => !f.Contains(".template.config", StringComparison.Ordinal)))
      Assert.DoesNotContain(SceneFolderTemplate.SourceName.ToLowerInvariant(), File.ReadAllText(f).ToLowerInvariant(), StringComparison.Ordinal);
    Assert.Contains($"\"sourceName\": \"{SceneFolderTemplate.SourceName}\"",
      File.ReadAllText(Path.Combine(TemplateFolder, ".template.config", "template.json")), StringComparison.Ordinal);
  }

  [Fact]
  public void Init_without_a_folder_uses_the_current_one_and_its_name()
  {
    using var tmp = new TempDirectory();
    string folder = tmp.File("orbit-homework");
    Directory.CreateDirectory(folder);
    CliRun run = CliRun.Of(folder, "init");

    Assert.True(run.ExitCode == 0, run.Error);
    Assert.True(File.Exists(Path.Combine(folder, "orbit-homework.csproj")));
    Assert.True(File.Exists(Path.Combine(folder, "Scene.cs")));
    Assert.True(File.Exists(Path.Combine(folder, "Shim", "ScriptGlobals.cs")));
  }

  [Fact]
  public void Init_script_renders_through_the_cli_as_written()
  {
    using var tmp = new TempDirectory();
    Assert.Equal(0, CliRun.Of(tmp.Path, "init", "scene").ExitCode);

    CliRun render = CliRun.Of(tmp.Path, "render", "scene/Scene.cs", "--param", "radius=0.8", "--size", "80x60", "-o", "out.png", "-q");

    Assert.True(render.ExitCode == 0, render.Error);
    FloatImage image = ImageFile.Load(tmp.File("out.png"));
    Assert.Equal((80, 60), (image.Width, image.Height));
    // The orange ball fills the middle, the dark background the top corners.
    double[] middle = image.GetPixel(40, 30), corner = image.GetPixel(2, 2);
    Assert.True(middle[0] > 0.3 && middle[0] > middle[2], $"middle pixel {string.Join(", ", middle)}");
    Assert.True(corner[0] < 0.1, $"corner pixel {string.Join(", ", corner)}");
  }

  [Fact]
  public void Init_refuses_to_replace_a_file_and_writes_nothing()
  {
    using var tmp = new TempDirectory();
    string folder = tmp.File("mine");
    Directory.CreateDirectory(folder);
    File.WriteAllText(Path.Combine(folder, "Scene.cs"), "// my own scene\n");

    CliRun run = CliRun.Of(tmp.Path, "init", "mine");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains("already has Scene.cs", run.Error, StringComparison.Ordinal);
    Assert.Contains("nothing written", run.Error, StringComparison.Ordinal);
    Assert.Equal("// my own scene\n", File.ReadAllText(Path.Combine(folder, "Scene.cs")));
    Assert.Equal(new[] { Path.Combine(folder, "Scene.cs") }, tmp.AllFiles());
    Assert.Empty(Directory.GetDirectories(folder));
  }

  [Fact]
  public void Init_a_second_time_names_every_file_it_would_replace()
  {
    using var tmp = new TempDirectory();
    Assert.Equal(0, CliRun.Of(tmp.Path, "init", "s").ExitCode);
    string before = string.Join("\n", tmp.AllFiles().Order(StringComparer.Ordinal).Select(File.ReadAllText));

    CliRun again = CliRun.Of(tmp.Path, "init", "s");

    Assert.Equal(ExitCodes.Failure, again.ExitCode);
    Assert.Contains("s.csproj", again.Error, StringComparison.Ordinal);
    Assert.Contains("Scene.cs", again.Error, StringComparison.Ordinal);
    Assert.Equal(before, string.Join("\n", tmp.AllFiles().Order(StringComparer.Ordinal).Select(File.ReadAllText)));
  }

  [Fact]
  public void Init_on_a_file_is_a_usage_error()
  {
    using var tmp = new TempDirectory();
    File.WriteAllText(tmp.File("notes.txt"), "x");

    CliRun run = CliRun.Of(tmp.Path, "init", "notes.txt");

    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.Contains("notes.txt: is a file", run.Error, StringComparison.Ordinal);
    Assert.Single(tmp.AllFiles());
  }

  [Fact]
  public void Init_that_fails_midway_removes_what_it_wrote()
  {
    using var tmp = new TempDirectory();
    string folder = tmp.File("half");
    Directory.CreateDirectory(folder);
    // A file where the shim's folder goes: the files before it are written, then the folder cannot be made.
    File.WriteAllText(Path.Combine(folder, "Shim"), "in the way");

    CliRun run = CliRun.Of(tmp.Path, "init", "half");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains("nothing written", run.Error, StringComparison.Ordinal);
    Assert.Equal(new[] { Path.Combine(folder, "Shim") }, tmp.AllFiles());
  }
}
