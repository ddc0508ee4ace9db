using System;
using System.Collections.Generic;
using System.Linq;
using Rendering;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class SceneCatalogTests
{
  [Fact]
  public void Render_to_switch_is_parsed_and_reaches_the_controller()
  {
    var cl = DemoCommandLine.Parse(new[] { "-render-to", "out.png", "-nodefault" });
    Assert.Equal("out.png", cl.RenderTo);
    Assert.Empty(cl.Errors);
    Assert.Contains("-render-to needs a path", Assert.Single(DemoCommandLine.Parse(new[] { "-render-to" }).Errors));
    using var controller = DemoController.FromCommandLine(new[] { "-nodefault", "--render-to", "x.png" }, null, new List<string>());
    Assert.Equal("x.png", controller.RenderTo);
  }

  [Fact]
  public void Command_line_reads_dir_scene_and_nodefault_like_grcis()
  {
    var cl = DemoCommandLine.Parse(new[] { "-dir", "scripts", "--scene", "a.cs", "-nodefault", "b.cs", "-bogus", "-scene" });
    Assert.Equal(new[] { "scripts" }, cl.Directories);
    Assert.Equal(new[] { "a.cs", "b.cs" }, cl.SceneFiles);
    Assert.True(cl.NoDefault);
    Assert.Equal(2, cl.Errors.Count);
    Assert.Contains(cl.Errors, e => e.Contains("-bogus"));
  }

  [Fact]
  public void Folder_and_single_files_are_listed_once_by_file_name()
  {
    using var tmp = new TempDir();
    System.IO.File.WriteAllText(tmp.File("Zeta.cs"), TestScripts.Background(0.1));
    System.IO.File.WriteAllText(tmp.File("Alpha.cs"), TestScripts.Background(0.2));
    System.IO.File.WriteAllText(tmp.File("notes.txt"), "not a script");
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Plane", _ => TestScenes.PlaneAt(5), tooltip: "no parameters");
    int changes = 0;
    catalog.Changed += (_, _) => changes++;

    Assert.Equal(2, catalog.AddScriptsFolder(tmp.Path));
    SceneEntry again = catalog.AddScriptFile(tmp.File("Alpha.cs"));

    Assert.Equal(new[] { "Plane", "Alpha", "Zeta" }, catalog.Entries.Select(e => e.Name));
    Assert.Same(catalog.Find("alpha"), again);
    Assert.Equal(SceneEntryKind.Script, again.Kind);
    Assert.Equal(1, changes);
    Assert.Throws<SceneEvaluationException>(() => catalog.AddScriptFile(tmp.File("missing.cs")));
  }

  [Fact]
  public void From_command_line_adds_builtins_unless_nodefault()
  {
    using var tmp = new TempDir();
    System.IO.File.WriteAllText(tmp.File("One.cs"), TestScripts.Background(0.1));
    void BuiltIns(SceneCatalog c) => c.AddBuiltIn("Plane", _ => TestScenes.PlaneAt(5));

    var with = new SceneCatalog();
    with.AddFromCommandLine(DemoCommandLine.Parse(new[] { "-scene", tmp.File("One.cs") }), BuiltIns);
    var without = new SceneCatalog();
    without.AddFromCommandLine(DemoCommandLine.Parse(new[] { "-dir", tmp.Path, "-nodefault" }), BuiltIns);

    Assert.Equal(new[] { "Plane", "One" }, with.Entries.Select(e => e.Name));
    Assert.Equal(new[] { "One" }, without.Entries.Select(e => e.Name));
  }

  [Fact]
  public void From_command_line_selects_the_first_script_of_the_folders_over_the_default_scene()
  {
    using var tmp = new TempDir();
    System.IO.Directory.CreateDirectory(tmp.File("b"));
    System.IO.File.WriteAllText(tmp.File("b/Zeta.cs"), TestScripts.Background(0.1));
    System.IO.File.WriteAllText(tmp.File("b/alpha.cs"), TestScripts.Background(0.2));
    System.IO.File.WriteAllText(tmp.File("Single.cs"), TestScripts.Background(0.3));
    void BuiltIns(SceneCatalog c) => c.AddBuiltIn(BuiltInScenes.DefaultName, _ => TestScenes.PlaneAt(5));

    // As `grcis studio scripts/` starts: the built-in scenes, then the folder; its first script (by name) is selected.
    Assert.Equal("alpha", new SceneCatalog().AddFromCommandLine(DemoCommandLine.Parse(new[] { "-dir", tmp.File("b") }), BuiltIns)!.Name);
    // A script file named on its own comes first; without scripts, GrCis's default scene.
    Assert.Equal("Single", new SceneCatalog().AddFromCommandLine(DemoCommandLine.Parse(new[] { "-dir", tmp.File("b"), "-scene", tmp.File("Single.cs") }), BuiltIns)!.Name);
    Assert.Equal(BuiltInScenes.DefaultName, new SceneCatalog().AddFromCommandLine(DemoCommandLine.Parse(Array.Empty<string>()), BuiltIns)!.Name);
  }

  [Fact]
  public void Scripts_are_labelled_by_file_name_apart_from_built_in_scenes()
  {
    using var tmp = new TempDir();
    System.IO.Directory.CreateDirectory(tmp.File("other"));
    System.IO.File.WriteAllText(tmp.File("Bezier.cs"), TestScripts.Background(0.1));
    System.IO.File.WriteAllText(tmp.File("FiveBalls.cs"), TestScripts.Background(0.1));
    System.IO.File.WriteAllText(tmp.File("other/Bezier.cs"), TestScripts.Background(0.2));
    var catalog = new SceneCatalog();
    catalog.AddBuiltIn("Bezier", _ => TestScenes.PlaneAt(5));
    catalog.AddBuiltIn("Five balls", _ => TestScenes.PlaneAt(5));
    catalog.AddScriptsFolder(tmp.Path);
    catalog.AddScriptFile(tmp.File("other/Bezier.cs"));

    Assert.Equal(new[] { "Bezier", "Five balls", "Bezier (2)", "FiveBalls", "Bezier (3)" }, catalog.Entries.Select(e => e.Name));
    Assert.Equal(new[] { "Bezier", "Five balls", "Bezier.cs", "FiveBalls.cs", "Bezier.cs (2)" }, catalog.Entries.Select(e => e.Label));
    // The WinForms list shows ToString().
    Assert.Equal(catalog.Entries.Select(e => e.Label), catalog.Entries.Select(e => e.ToString()));
  }

  [Fact]
  public void Built_in_scene_gets_the_parameter_text()
  {
    string? seen = null;
    var catalog = new SceneCatalog();
    SceneEntry e = catalog.AddBuiltIn("Plane", p => { seen = p; return TestScenes.PlaneAt(5); }, "depth=…", defaultParam: "z=5");
    BuiltScene built = catalog.Build(e, e.ParameterText, new RenderSettings());
    Assert.Equal("z=5", seen);
    Assert.Equal("depth=…", built.Tooltip);
    Assert.True(built.Overrides.IsEmpty);
  }

  [Fact]
  public void Script_reports_tooltip_and_overrides_and_renders_its_background()
  {
    using var tmp = new TempDir();
    System.IO.File.WriteAllText(tmp.File("Bg.cs"), TestScripts.Background(0.25));
    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    SceneEntry entry = catalog.AddScriptFile(tmp.File("Bg.cs"));
    Assert.Null(entry.Tooltip);

    BuiltScene built = catalog.Build(entry, "g=0.125", new RenderSettings { Width = 640, Height = 480 });

    Assert.Equal("g = green (0 to 1)", entry.Tooltip);
    Assert.Equal(40, entry.Overrides!.Width);
    Assert.Equal(30, entry.Overrides.Height);
    Assert.Null(entry.Overrides.Supersampling);
    Assert.Equal(2.0, entry.Overrides.End);
    Assert.Contains("40x30", entry.Overrides.ToString());

    RenderJob job = built.ToJob();
    Assert.Equal((40, 30), (job.Width, job.Height));
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    Assert.Equal(new[] { 0.25, 0.125, 0.75 }, image.GetPixel(20, 15));
  }

  [Fact]
  public void Broken_script_is_a_message_naming_file_and_line()
  {
    using var tmp = new TempDir();
    System.IO.File.WriteAllText(tmp.File("Bad.cs"), "scene.BackgroundColor = new double[] { 1, 2 };\nthis is not C#;\n");
    using var evaluator = new GrCis.Scripting.ScriptHost();
    var catalog = new SceneCatalog(evaluator);
    var ex = Assert.Throws<SceneEvaluationException>(() => catalog.Build(catalog.AddScriptFile(tmp.File("Bad.cs")), "", new RenderSettings()));
    Assert.Contains("Bad.cs", ex.Message);
    Assert.Contains("(2,", ex.Message);
  }

  [Fact]
  public void Script_without_a_host_is_a_clear_message()
  {
    using var tmp = new TempDir();
    System.IO.File.WriteAllText(tmp.File("Bg.cs"), TestScripts.Background(0.25));
    var catalog = new SceneCatalog();
    var ex = Assert.Throws<SceneEvaluationException>(() => catalog.Build(catalog.AddScriptFile(tmp.File("Bg.cs")), "", new RenderSettings()));
    Assert.Contains("script host", ex.Message);
  }
}
