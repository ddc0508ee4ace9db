using System;
using System.IO;
using System.Linq;
using Rendering.Imaging;

namespace GrCis.Cli.Tests;

/// <summary><c>grcis render script.cs</c>: parameters, modules, time, and errors a student can read.</summary>
public class ScriptCommandTests
{
  /// <summary>A small scene: a sphere on a plane, lit by an ambient and a point light.</summary>
  internal const string SceneBody = """
    CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.6, 0.4, 16));
    scene.Intersectable = root;
    scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };
    scene.Camera = new StaticCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 1.0), 50.0);
    scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
    scene.Sources.Add(new AmbientLightSource(0.8));
    scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 3.0, -3.0), 1.0));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    Plane pl = new Plane();
    pl.SetAttribute(PropertyName.COLOR, new double[] { 0.5, 0.0, 0.0 });
    root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

    """;

  static string Write(TempDirectory dir, string name, string text)
  {
    string path = dir.File(name);
    Directory.CreateDirectory(Path.GetDirectoryName(path)!);
    File.WriteAllText(path, text.Replace("\r\n", "\n"));
    return path;
  }

  static void AssertNoImage(TempDirectory dir) =>
    Assert.DoesNotContain(dir.AllFiles(), f => f.EndsWith(".png", StringComparison.Ordinal) || f.Contains(".tmp", StringComparison.Ordinal));

  [Fact]
  public void Script_from_the_scripts_folder_renders_with_params()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", RepoPaths.Script("TwoSpheres.cs"), "--param", "n=1.5,rc", "--size", "40x30", "-o", "two.png");

    Assert.Equal(0, run.ExitCode);
    Rgb8Image image = PngFile.Load(dir.File("two.png"));
    Assert.Equal(40, image.Width);
    Assert.Contains("two.png: 40x30", run.Out);
  }

  [Fact]
  public void Default_output_name_comes_from_the_script_file()
  {
    using var dir = new TempDirectory();
    string script = Write(dir, "My Scene.cs", SceneBody);
    CliRun run = CliRun.Of(dir.Path, "render", script, "--size", "16x12", "-q");
    Assert.Equal(0, run.ExitCode);
    Assert.True(File.Exists(dir.File("my-scene.png")), run.Out + run.Error);
  }

  [Fact]
  public void Compile_errors_print_every_diagnostic_with_path_line_and_column_and_write_nothing()
  {
    using var dir = new TempDirectory();
    string script = Write(dir, "broken.cs", """
      Sphere s = new Sphere();
      int x = "text";
      scene.Intersectable = s;
      undefinedName.Foo();

      """);
    CliRun run = CliRun.Of(dir.Path, "render", script, "-o", "out.png");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains($"{script}(2,9): error CS0029: Cannot implicitly convert type 'string' to 'int'", run.ErrorLines);
    Assert.Contains(run.ErrorLines, l => l.StartsWith($"{script}(4,1): error CS0103: The name 'undefinedName' does not exist", StringComparison.Ordinal));
    Assert.Equal($"grcis: error: scene script '{script}' did not compile (2 errors)", run.ErrorLines[^1]);
    Assert.Equal("", run.Out);
    AssertNoImage(dir);
  }

  [Fact]
  public void Info_on_a_broken_script_prints_the_same_diagnostics()
  {
    using var dir = new TempDirectory();
    string script = Write(dir, "broken.cs", "scene.Intersectable = new Spher();\n");
    CliRun run = CliRun.Of(dir.Path, "info", script);

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.StartsWith($"{script}(1,27): error CS0246: The type or namespace name 'Spher' could not be found", run.ErrorLines[0]);
  }

  [Fact]
  public void Script_that_throws_reports_its_own_line_and_writes_nothing()
  {
    using var dir = new TempDirectory();
    string script = Write(dir, "throws.cs", SceneBody + """
      int[] a = new int[2];
      a[5] = 1;

      """);
    int line = SceneBody.Split('\n').Length + 1;
    CliRun run = CliRun.Of(dir.Path, "render", script, "-o", "out.png");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Equal($"grcis: error: {script}({line},1): runtime error: IndexOutOfRangeException: Index was outside the bounds of the array.", run.ErrorLines.Single());
    AssertNoImage(dir);
  }

  [Fact]
  public void Script_class_that_throws_while_rendering_reports_the_script_line()
  {
    using var dir = new TempDirectory();
    string script = Write(dir, "badtexture.cs", SceneBody + """
      pl.SetAttribute(PropertyName.TEXTURE, new Broken());

      class Broken : ITexture
      {
        public long Apply(Intersection inter)
        {
          throw new InvalidOperationException("texture exploded");
        }
      }

      """);
    int line = SceneBody.Split('\n').Length + 6;
    CliRun run = CliRun.Of(dir.Path, "render", script, "--size", "16x12", "-o", "out.png", "-q");

    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.Contains($"{script}({line},", run.Error);
    Assert.Contains("runtime error: InvalidOperationException: texture exploded", run.Error);
    AssertNoImage(dir);
  }

  [Fact]
  public void Bad_parameter_value_is_a_clear_usage_error()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", RepoPaths.Script("Spiral.cs"), "--param", "count=abc", "-o", "out.png");

    Assert.Equal(ExitCodes.Usage, run.ExitCode);
    Assert.StartsWith("grcis: error: invalid --param: parameter 'count' has the value 'abc', expected a whole number", run.ErrorLines.Single());
    AssertNoImage(dir);
  }

  [Fact]
  public void Missing_script_and_missing_module_folder_are_usage_errors()
  {
    using var dir = new TempDirectory();
    CliRun missing = CliRun.Of(dir.Path, "render", "nothere.cs", "-o", "x.png");
    Assert.Equal(ExitCodes.Usage, missing.ExitCode);
    Assert.Equal($"grcis: error: scene script 'nothere.cs' not found (looked for '{dir.File("nothere.cs")}')", missing.ErrorLines.Single());

    string script = Write(dir, "ok.cs", SceneBody);
    CliRun noModule = CliRun.Of(dir.Path, "render", script, "--module", "mods", "-o", "x.png");
    Assert.Equal(ExitCodes.Usage, noModule.ExitCode);
    Assert.Contains("module folder 'mods' not found", noModule.Error);

    CliRun moduleForBuiltIn = CliRun.Of(dir.Path, "render", "Five balls", "--module", dir.Path, "-o", "x.png");
    Assert.Equal(ExitCodes.Usage, moduleForBuiltIn.ExitCode);
    Assert.Contains("--module works only with a scene script", moduleForBuiltIn.Error);
    AssertNoImage(dir);
  }

  [Fact]
  public void Module_folder_provides_classes_to_the_script()
  {
    using var dir = new TempDirectory();
    Write(dir, "mods/Author/GreenTexture.cs", """
      using Rendering;

      namespace SomeAuthor;

      public class GreenTexture : ITexture
      {
        public long Apply(Intersection inter)
        {
          inter.SurfaceColor = new double[] { 0.0, 1.0, 0.0 };
          return 7L;
        }
      }
      """);
    string script = Write(dir, "usesmodule.cs", "using SomeAuthor;\n" + SceneBody + "pl.SetAttribute(PropertyName.TEXTURE, new GreenTexture());\n");

    CliRun run = CliRun.Of(dir.Path, "render", script, "--module", "mods", "--size", "32x24", "-o", "m.png", "-q");
    Assert.Equal(0, run.ExitCode);
    Rgb8Image image = PngFile.Load(dir.File("m.png"));
    // The bottom row shows the plane: green (the dark red plane colour is replaced; highlights are white).
    int i = image.PixelIndex(16, 23);
    Assert.True(image.Data[i + 1] > 100 && image.Data[i + 1] > 2 * image.Data[i], $"expected a green floor, got {image.Data[i]},{image.Data[i + 1]},{image.Data[i + 2]}");
  }

  [Fact]
  public void Module_that_does_not_compile_prints_its_diagnostics()
  {
    using var dir = new TempDirectory();
    string file = Write(dir, "mods/Bad.cs", "namespace Bad;\npublic class X { int y = \"no\"; }\n");
    string script = Write(dir, "s.cs", SceneBody);

    CliRun run = CliRun.Of(dir.Path, "render", script, "--module", "mods", "-o", "x.png");
    Assert.Equal(ExitCodes.Failure, run.ExitCode);
    Assert.StartsWith($"{file}(2,26): error CS0029:", run.ErrorLines[0]);
    Assert.Contains("did not compile (1 error)", run.ErrorLines[^1]);
    AssertNoImage(dir);
  }

  [Fact]
  public void Time_option_renders_an_animated_script_at_that_time()
  {
    using var dir = new TempDirectory();
    string orbit = RepoPaths.Script("Orbit.cs");
    CliRun a = CliRun.Of(dir.Path, "render", orbit, "--time", "0.5", "--size", "40x30", "-o", "a.png", "-q");
    CliRun b = CliRun.Of(dir.Path, "render", orbit, "--time", "2.5", "--size", "40x30", "-o", "b.png", "-q");
    CliRun a2 = CliRun.Of(dir.Path, "render", orbit, "--time", "0.5", "--size", "40x30", "-o", "a2.png", "-q");

    Assert.Equal(0, a.ExitCode);
    Assert.Equal(0, b.ExitCode);
    Assert.Equal(0, a2.ExitCode);
    byte[] pa = PngFile.Load(dir.File("a.png")).Data, pb = PngFile.Load(dir.File("b.png")).Data;
    Assert.NotEqual(pa, pb);
    Assert.Equal(pa, PngFile.Load(dir.File("a2.png")).Data);
  }

  [Fact]
  public void Script_time_is_the_default_and_the_time_option_overrides_it()
  {
    using var dir = new TempDirectory();
    // Orbit.cs with a Time of its own.
    string script = Write(dir, "OrbitAt.cs", File.ReadAllText(RepoPaths.Script("Orbit.cs")) + "\ncontext[PropertyName.CTX_TIME] = 2.5;\n");
    string orbit = RepoPaths.Script("Orbit.cs");
    Assert.Equal(0, CliRun.Of(dir.Path, "render", script, "--size", "40x30", "-o", "script.png", "-q").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", orbit, "--time", "2.5", "--size", "40x30", "-o", "at25.png", "-q").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", script, "--time", "0.5", "--size", "40x30", "-o", "override.png", "-q").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "render", orbit, "--time", "0.5", "--size", "40x30", "-o", "at05.png", "-q").ExitCode);

    Assert.Equal(PngFile.Load(dir.File("at25.png")).Data, PngFile.Load(dir.File("script.png")).Data);
    Assert.Equal(PngFile.Load(dir.File("at05.png")).Data, PngFile.Load(dir.File("override.png")).Data);
  }

  [Fact]
  public void Time_option_on_a_still_scene_is_noted_and_ignored()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "render", RepoPaths.Script("FiveBalls.cs"), "--time", "2", "--size", "16x12", "-o", "f.png", "-q");
    Assert.Equal(0, run.ExitCode);
    Assert.Contains("grcis: note: the scene does not change with time; --time is ignored", run.ErrorLines);
  }
}
