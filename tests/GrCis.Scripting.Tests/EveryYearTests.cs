using System;
using System.IO;
using System.Linq;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// Scripts and modules as students of each GrCis year wrote them: the script globals of 2018 and 2020, the
/// context GrCis filled before every call, overrides with another year's access, modules built as a Debug
/// project built them (DEBUG, TRACE, one assembly), and runtime errors that name the module line.
/// </summary>
public sealed class EveryYearTests() : ScratchScriptTests("grcis-years-")
{
  [Fact]
  public void A_March_2018_script_fills_sc_and_a_2018_to_2020_script_writes_outParam_and_reads_sceneName()
  {
    // 048rtmontecarlo-script of March 2018 named the scene 'sc'.
    ScriptScene first = host.Load(Write("Sc2018.cs", """
      sc.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };
      sc.Intersectable = new Sphere();
      """));
    Assert.Equal(new[] { 0.1, 0.2, 0.3 }, first.Scene.BackgroundColor);
    Assert.IsType<Sphere>(first.Scene.Intersectable);

    // From April 2018 to May 2020 the context was 'outParam' (062animation-script's AnimatedScene.cs style).
    ScriptScene second = host.Load(Write("OutParam2019.cs", """
      if (outParam != null)
      {
        outParam["Start"] = 0.0;
        outParam["End"] = 20.0;
      }
      outParam["name"] = sceneName;
      outParam["path"] = scriptFilePath;
      scene.Intersectable = new Sphere();
      """));
    Assert.Equal(20.0, second.End);
    Assert.Equal(0.0, second.Start);
    Assert.Equal("OutParam2019.cs", second.Context["name"]);
    Assert.Equal(Path.Combine(scratch.Path, "OutParam2019.cs"), second.Context["path"]);
  }

  [Fact]
  public void A_script_variable_or_method_parameter_named_like_an_old_global_hides_it()
  {
    ScriptScene run = host.Load(Write("Shadow.cs", """
      string sceneName = "mine";
      CSGInnerNode sc = new CSGInnerNode(SetOperation.Union);
      sc.InsertChild(new Sphere(), Matrix4d.Identity);
      scene.Intersectable = sc;
      int Count (Dictionary<string, object> outParam) => outParam.Count;
      context["name"] = sceneName;
      context["count"] = Count(new Dictionary<string, object> { ["a"] = 1 });
      """));
    Assert.Equal("mine", run.Context["name"]);
    Assert.Equal(1, run.Context["count"]);
    Assert.IsType<CSGInnerNode>(run.Scene.Intersectable);
  }

  [Fact]
  public void The_context_holds_GrCis_values_before_the_script_runs_and_only_what_the_script_writes_is_its_choice()
  {
    ScriptScene run = host.Load(Write("Reads.cs", """
      context["seen"] = $"{context[PropertyName.CTX_SCENE_NAME]} {context[PropertyName.CTX_WIDTH]}x{context[PropertyName.CTX_HEIGHT]} " +
                        $"ss{context[PropertyName.CTX_SUPERSAMPLING]} {context[PropertyName.CTX_START_ANIM]}-{context[PropertyName.CTX_END_ANIM]}@{context[PropertyName.CTX_FPS]}";
      if (context.TryGetValue(PropertyName.CTX_PREPROCESSING, out object pre) && (bool)pre)
      {
        context["preprocessed"] = true;
        return;
      }
      // A script that computes from the start time without setting it first (GrCis guarantees it since 2020).
      double start = (double)context[PropertyName.CTX_START_ANIM];
      context[PropertyName.CTX_END_ANIM] = start + 4.0;
      context[PropertyName.CTX_WIDTH] = 640;   // the same value as given: still the script's choice
      scene.Intersectable = new Sphere();
      """));
    Assert.Equal("Reads.cs 640x480 ss1 0-10@25", run.Context["seen"]);
    Assert.Equal(true, run.Context["preprocessed"]);
    Assert.Equal(4.0, run.End);
    Assert.Equal(640, run.Width);
    // Read, not written: not the script's.
    Assert.Null(run.Height);
    Assert.Null(run.SuperSampling);
    Assert.Null(run.Start);
    Assert.Null(run.Fps);
  }

  [Fact]
  public void A_front_ends_values_reach_the_script_and_are_not_taken_for_its_own()
  {
    string path = Write("Given.cs", """
      context["seen"] = $"{context[PropertyName.CTX_WIDTH]}x{context[PropertyName.CTX_HEIGHT]} ss{context[PropertyName.CTX_SUPERSAMPLING]} {context[PropertyName.CTX_FPS]} {context[PropertyName.CTX_SCENE_NAME]}";
      scene.Intersectable = new Sphere();
      """);
    var init = new ScriptContextInit { SceneName = "given", Width = 320, Height = 200, SuperSampling = 4, Fps = 12.0 };
    ScriptScene run = host.Run(host.Compile(path), "", null, null, init);
    Assert.Equal("320x200 ss4 12 given", run.Context["seen"]);
    Assert.Null(run.Width);
    Assert.Null(run.SuperSampling);
    Assert.Null(run.Fps);
  }

  [Fact]
  public void A_module_overriding_shade_as_protected_compiles_with_a_warning_at_its_line_and_renders_like_the_base()
  {
    // RayTracing.shade was protected virtual from 2012 to 2021; it is public now.
    Write("Tracer.cs", """
      using OpenTK;
      using Rendering;

      namespace Homework2019
      {
        public class CountingTracer : RayTracing
        {
          public static int Calls;

          protected override long shade (int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
          {
            System.Threading.Interlocked.Increment(ref Calls);
            return base.shade(depth, importance, ref p0, ref p1, color);
          }
        }
      }
      """);
    ScriptModule module = host.AddModule(scratch.Path + "/");
    ScriptDiagnostic warning = Assert.Single(module.Warnings, w => w.Id == ScriptDiagnostic.OverrideAccessId);
    Assert.Equal(Path.Combine(scratch.Path, "Tracer.cs"), warning.Path);
    Assert.Equal(10, warning.Line);
    Assert.Equal(5, warning.Column);
    Assert.Contains("'protected' is read as 'public'", warning.Message);

    string script = Path.Combine(scratch.Path, "..", Path.GetFileName(scratch.Path) + "-scene.cs");
    File.WriteAllText(script, "Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_ALGORITHM] = new Homework2019.CountingTracer();\n");
    try
    {
      ScriptScene run = host.Load(script);
      var tracer = (RayTracing)run.Algorithm!;
      FloatImage image = TileRenderer.Render(run.Scene, tracer, new SimpleImageSynthesizer { Width = 24, Height = 18 }, new RenderOptions { Threads = 1 });
      FloatImage plain = TileRenderer.Render(run.Scene, new RayTracing(), new SimpleImageSynthesizer { Width = 24, Height = 18 }, new RenderOptions { Threads = 1 });
      Assert.Equal(plain.Data, image.Data);
      Assert.True((int)tracer.GetType().GetField("Calls")!.GetValue(null)! >= 24 * 18);
    }
    finally
    {
      File.Delete(script);
    }
  }

  [Fact]
  public void An_override_made_wider_than_the_base_is_narrowed_and_later_errors_on_its_line_keep_their_columns()
  {
    // setTime is protected: a 'public override' is read as 'protected' (three characters longer).
    string path = Write("Wider.cs", """
      class Spinner : AnimatedCSGInnerNode
      {
        public Spinner () : base(SetOperation.Union) { }
        public override void setTime (double t) { base.setTime(t); } int x = "no";
      }
      scene.Intersectable = new Spinner();
      """);
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    ScriptDiagnostic error = Assert.Single(ex.Diagnostics, d => d.IsError);
    Assert.Equal("CS0029", error.Id);
    Assert.Equal(4, error.Line);
    // The column of "no" in the file as written, although the access keyword grew before it.
    Assert.Equal(File.ReadAllLines(path)[3].IndexOf("\"no\"", StringComparison.Ordinal) + 1, error.Column);
    ScriptDiagnostic warning = Assert.Single(ex.Diagnostics, d => d.Id == ScriptDiagnostic.OverrideAccessId);
    Assert.Equal(4, warning.Line);
    Assert.Contains("'public' is read as 'protected'", warning.Message);

    // Without the error the script compiles and its node animates.
    File.WriteAllText(path, File.ReadAllText(path).Replace(" int x = \"no\";", ""));
    ScriptScene run = host.Load(path);
    var node = Assert.IsAssignableFrom<AnimatedCSGInnerNode>(run.Scene.Intersectable);
    node.Time = 2.5;
    Assert.Equal(2.5, node.Time);
  }

  [Fact]
  public void Modules_are_built_with_DEBUG_and_TRACE_defined_as_a_students_Debug_build()
  {
    string dir = Path.Combine(scratch.Path, "mod");
    Write("mod/Checks.cs", """
      namespace Checks
      {
        public static class Build
        {
      #if DEBUG
          public const string Debug = "DEBUG";
      #else
          public const string Debug = "";
      #endif
      #if TRACE
          public const string Trace = "TRACE";
      #else
          public const string Trace = "";
      #endif
        }
      }
      """);
    host.AddModule(dir);
    ScriptScene run = host.Load(Write("UsesChecks.cs", """
      context["symbols"] = Checks.Build.Debug + Checks.Build.Trace;
      scene.Intersectable = new Sphere();
      """));
    Assert.Equal("DEBUGTRACE", run.Context["symbols"]);
  }

  [Fact]
  public void Module_folders_given_together_are_one_assembly_whose_classes_use_each_other_both_ways()
  {
    Write("solids/Ring.cs", """
      using Rendering;
      namespace Solids
      {
        public class Ring : CSGInnerNode
        {
          public Ring () : base(SetOperation.Union) { }
          public Materials.Palette Palette = new Materials.Palette();
        }
      }
      """);
    Write("materials/Palette.cs", """
      namespace Materials
      {
        public class Palette
        {
          public double[] Gold = { 1.0, 0.8, 0.1 };
          public static Solids.Ring Sample () => new Solids.Ring();
        }
      }
      """);
    ScriptModule module = host.AddModules(new[] { Path.Combine(scratch.Path, "solids"), Path.Combine(scratch.Path, "materials") });
    Assert.Equal(2, module.Directories.Count);
    Assert.Single(host.Modules);
    ScriptScene run = host.Load(Write("Ring.cs", """
      var ring = Materials.Palette.Sample();
      ring.InsertChild(new Sphere(), Matrix4d.Identity);
      ring.SetAttribute(PropertyName.COLOR, ring.Palette.Gold);
      scene.Intersectable = ring;
      """));
    Assert.Equal("Solids.Ring", run.Scene.Intersectable!.GetType().FullName);
  }

  [Fact]
  public void An_exception_thrown_in_module_code_while_rendering_names_the_module_file_and_line()
  {
    string dir = Path.Combine(scratch.Path, "tex");
    Write("tex/Broken.cs", """
      using Rendering;

      namespace Textures2020
      {
        public class Broken : ITexture
        {
          public long Apply (Intersection inter)
          {
            double[] c = inter.SurfaceColor;
            if (inter.T > 0.0)
              throw new System.InvalidOperationException("texture table not loaded");
            return 0L;
          }
        }
      }
      """);
    host.AddModule(dir);
    string script = Write("Textured.cs", """
      var root = new CSGInnerNode(SetOperation.Union);
      var ball = new Sphere();
      ball.SetAttribute(PropertyName.TEXTURE, new Textures2020.Broken());
      root.InsertChild(ball, Matrix4d.Identity);
      scene.Intersectable = root;
      scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 40);
      scene.Sources = new List<ILightSource> { new PointLightSource(new Vector3d(-5, 5, -5), 1.0) };
      """);
    ScriptScene run = host.Load(script);
    var failure = Assert.ThrowsAny<Exception>(() =>
      TileRenderer.Render(run.Scene, new RayTracing(), new SimpleImageSynthesizer { Width = 16, Height = 12 }, new RenderOptions { Threads = 1 }));
    ScriptRuntimeException located = Assert.IsType<ScriptRuntimeException>(run.Script.FindScriptLine(failure));
    Assert.Equal(Path.Combine(dir, "Broken.cs"), located.Path);
    Assert.Equal(11, located.Line);
    Assert.Contains("Broken.cs(11,", located.Message);
    Assert.Contains("runtime error: InvalidOperationException: texture table not loaded", located.Message);
  }
  [Fact]
  public void A_script_from_before_the_preprocessing_call_finds_an_animated_scene_in_every_call_and_scriptFileName()
  {
    // Written in May 2020 on the branch that proposed scriptFileName, before the preprocessing call existed.
    string path = Write("Before2020.cs", """
      (scene as ITimeDependent).End = 4.0;
      context["file"] = scriptFileName;
      scene.Intersectable = new Sphere();
      """);
    ScriptScene run = host.Run(host.Compile(path), "", null, new AnimatedRayScene());
    Assert.True(run.Preprocessed);
    Assert.Equal(4.0, ((ITimeDependent)run.Scene).End);
    Assert.Equal(path, run.Context["file"]);
  }

  [Fact]
  public void Data_files_a_student_reads_with_dotnets_file_api_are_found_as_GrCis_on_Windows_found_them()
  {
    // A fork's layout: the script in data/rtscenes, its files named for the project's bin/Debug working folder.
    Write("fork/data/rtscenes/Camera_Script.TXT", "0 0 -5\n");
    Write("fork/data/rtscenes/table.csv", "1;2;3\n");
    string dir = Path.Combine(scratch.Path, "fork", "062animation-script", "Reader");
    Write("fork/062animation-script/Reader/PathReader.cs", """
      using System.IO;

      namespace Reader
      {
        public static class PathReader
        {
          public static string FirstLine (string fileName)
          {
            if (!File.Exists(fileName))
              throw new IOException("Please specify a file with camera script.");
            using (StreamReader sr = new StreamReader(fileName))
              return sr.ReadLine();
          }
        }
      }
      """);
    host.AddModule(dir);
    string script = Write("fork/data/rtscenes/Reads.cs", """
      context["camera"] = Reader.PathReader.FirstLine("..\\..\\..\\data\\rtscenes\\camera_script.txt");
      context["table"] = System.IO.File.ReadAllText(path: "table.csv").Trim();
      System.IO.File.WriteAllText(System.IO.Path.Combine(System.IO.Path.GetDirectoryName(scriptFilePath), "out.txt"), "written");
      scene.Intersectable = new Sphere();
      """);
    ScriptScene run = host.Load(script);
    Assert.Equal("0 0 -5", run.Context["camera"]);
    Assert.Equal("1;2;3", run.Context["table"]);
    Assert.Equal("written", File.ReadAllText(Path.Combine(scratch.Path, "fork", "data", "rtscenes", "out.txt")));
  }

  [Fact]
  public void A_compile_error_after_a_rewritten_file_call_keeps_its_column()
  {
    string path = Write("Column.cs", """
      string t = System.IO.File.ReadAllText("a.txt"); int n = "x";
      """);
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    ScriptDiagnostic error = Assert.Single(ex.Diagnostics, d => d.IsError);
    Assert.Equal((1, File.ReadAllLines(path)[0].IndexOf("\"x\"", StringComparison.Ordinal) + 1), (error.Line, error.Column));
  }
  [Fact]
  public void A_module_type_with_the_full_name_of_a_later_library_type_is_the_one_its_module_and_scripts_use()
  {
    // Written in May 2020, a week before GrCis got a Rendering.AnimatedCamera of its own.
    string dir = Path.Combine(scratch.Path, "rt_extensions");
    Write("rt_extensions/AnimatedCamera.cs", """
      using OpenTK;

      namespace Rendering
      {
        public class AnimatedCamera : StaticCamera
        {
          public string Script;

          public AnimatedCamera (string script) : base(new Vector3d(0, 0, -5), Vector3d.UnitZ, 40.0)
          {
            Script = script;
          }

          public static AnimatedCamera Default () => new AnimatedCamera("default");
        }
      }
      """);
    Write("rt_extensions/Rig.cs", """
      namespace Rendering
      {
        public static class Rig
        {
          public static AnimatedCamera Make (string s) { AnimatedCamera c = new AnimatedCamera(s); return c; }
        }
      }
      """);
    ScriptModule module = host.AddModule(dir);
    ScriptDiagnostic warning = Assert.Single(module.Warnings, w => w.Id == ScriptDiagnostic.ShadowedLibraryTypeId);
    Assert.Equal((Path.Combine(dir, "AnimatedCamera.cs"), 5, 16), (warning.Path, warning.Line, warning.Column));

    ScriptScene run = host.Load(Write("Cubes.cs", """
      AnimatedCamera camera = new AnimatedCamera("camera_script.txt");
      scene.Camera = camera;
      context["rig"] = Rig.Make("rig").Script + " " + AnimatedCamera.Default().Script;
      scene.Intersectable = new Sphere();
      """));
    Assert.Equal(module.Assembly, run.Scene.Camera!.GetType().Assembly);
    Assert.Equal("rig default", run.Context["rig"]);

    // Errors in the script still point at the user's own line and column.
    string broken = Write("Broken.cs", "AnimatedCamera c = new AnimatedCamera(1);\n");
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(broken));
    ScriptDiagnostic error = Assert.Single(ex.Diagnostics, d => d.IsError);
    Assert.Equal((1, 39), (error.Line, error.Column));
  }
  [Fact]
  public void A_module_adding_to_a_library_class_with_partial_is_told_why_it_cannot()
  {
    // A student's OBJ loader of 2020 added methods to GrCis's SceneBrep, which its project compiled in.
    string dir = Path.Combine(scratch.Path, "objloader");
    Write("objloader/ObjLoader.cs", """
      namespace Scene3D
      {
        public partial class SceneBrep
        {
          public int LoadObj (string file) { BuildCornerTable(); return 0; }
        }
      }
      """);
    var ex = Assert.Throws<ScriptCompilationException>(() => host.AddModule(dir));
    ScriptDiagnostic first = ex.Diagnostics[0];
    Assert.Equal((ScriptDiagnostic.PartialLibraryTypeId, 3, 24), (first.Id, first.Line, first.Column));
    Assert.Contains("'Scene3D.SceneBrep' adds to a class of the library", first.Message);
    // The library's SceneBrep is not renamed or shadowed by the failed attempt.
    Assert.Empty(host.Modules);
  }
}
