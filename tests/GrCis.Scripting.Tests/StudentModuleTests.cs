using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// A student's homework folder as GrCis users keep it: classes written against OpenTK 3
/// (<c>using OpenTK;</c>), the scene scripts beside them, build output of the old project,
/// and a 049-style <c>DistributedRayTracing</c> that overrides <c>shade</c>, chosen by the script
/// through <c>context</c>.
/// </summary>
public sealed class StudentModuleTests : IDisposable
{
  readonly ScratchFolder scratch = new("grcis-homework-");

  public void Dispose() => scratch.Dispose();

  string Write(string relative, string text) => scratch.Write(relative, text);

  const string Tracer = """
    using System;
    using System.Collections.Generic;
    using OpenTK;
    using MathSupport;
    using Rendering;
    using Utilities;

    namespace Homework049
    {
      /// A homework-style tracer: counts its rays GrCis's way, then shades as the base class does.
      public class DistributedRayTracing : RayTracing
      {
        public static int PrimaryRays;

        public DistributedRayTracing () : base()
        {
          MaxLevel = 8;
        }

        public override long shade (int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
        {
          Statistics.IncrementRaysCounters(1, depth == 0);
          if (depth == 0)
            System.Threading.Interlocked.Increment(ref PrimaryRays);
          if (MT.singleRayTracing)
            rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.unknown, depth, p0);
          Master.singleton?.pointCloud?.AddToPointCloud(p0, color, p1, MT.threadID);
          Vector4d h = new Vector4d(p1, 0.0);
          Vector3d back = Vector3d.TransformVector(h.Xyz, Matrix4d.Identity);
          double k = Util.Clamp(Arith.Pow(back.Length, 2), 0.0, 2.0);
          long hash = base.shade(depth, importance, ref p0, ref p1, color);
          return k > 0.0 ? hash : hash + 1;
        }
      }
    }
    """;

  const string Camera = """
    using OpenTK;
    using Rendering;

    namespace Homework049
    {
      public class LookAtCamera : StaticCamera
      {
        public LookAtCamera (Vector3d eye, Vector3d target, double degrees)
        {
          center = eye;
          direction = (target - eye).Normalized();
          hAngle = MathHelper.DegreesToRadians(degrees);
          Width = 40;
          Height = 30;
        }
      }
    }
    """;

  // The student's scene script, kept in the same folder: it must not be compiled into the module.
  const string Scene = """
    using Homework049;

    Scenes.FiveBalls(scene);
    scene.Camera = new LookAtCamera(new Vector3d(0.7, 0.5, -5.0), new Vector3d(0.0, -0.18, 0.0), 50.0);
    context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
    context[PropertyName.CTX_WIDTH] = 40;
    context[PropertyName.CTX_HEIGHT] = 30;
    """;

  [Fact]
  public void A_homework_folder_with_scripts_and_build_output_compiles_as_a_module_and_its_tracer_renders()
  {
    Write("DistributedRayTracing.cs", Tracer);
    Write("LookAtCamera.cs", Camera);
    string script = Write("DistributedScene.cs", Scene);
    Write("Scenes/Other.cs", "scene.BackgroundColor = new double[] { 1, 0, 0 };\n");
    // An old project's generated file: compiling it would add a second set of assembly attributes.
    Write("obj/Debug/Homework049.AssemblyInfo.cs",
      "[assembly: System.Reflection.AssemblyTitle(\"x\")]\n[assembly: System.Reflection.AssemblyTitle(\"y\")]\n");

    using var host = new ScriptHost();
    ScriptModule module = host.AddModule(scratch.Path);
    Assert.Equal(new[] { "DistributedRayTracing.cs", "LookAtCamera.cs" }, module.Files.Select(Path.GetFileName));
    Assert.Equal(new[] { script, Path.Combine(scratch.Path, "Scenes", "Other.cs") }, module.SkippedScripts);

    ScriptScene run = host.Load(script);
    Assert.Equal("Homework049.DistributedRayTracing", run.Algorithm!.GetType().FullName);
    var rt = (RayTracing)run.Algorithm;
    Assert.Equal(8, rt.MaxLevel);

    var renderer = new SimpleImageSynthesizer { Width = 40, Height = 30 };
    FloatImage image = TileRenderer.Render(run.Scene, rt, renderer, new RenderOptions { Threads = 2 });
    Type type = run.Algorithm.GetType();
    Assert.Equal(40 * 30, (int)type.GetField("PrimaryRays")!.GetValue(null)!);

    // Its shade delegates to the base: the picture is plain ray tracing's.
    var plain = new RayTracing { MaxLevel = 8 };
    FloatImage expected = TileRenderer.Render(run.Scene, plain, new SimpleImageSynthesizer { Width = 40, Height = 30 }, new RenderOptions { Threads = 2 });
    Assert.Equal(expected.Data, image.Data);
  }

  [Fact]
  public void A_049_module_declaring_its_own_Rendering_DistributedRayTracing_wins_over_the_librarys()
  {
    // GrCis's 049 skeleton declares DistributedRayTracing in namespace Rendering, as the library now does too.
    Write("DistributedRT.cs", """
      using System;
      using OpenTK;
      using Rendering;

      namespace Rendering
      {
        public class DistributedRayTracing : RayTracing
        {
          public static int Calls;

          public DistributedRayTracing (IRayScene sc) : base(sc)
          {
          }

          public override long shade (int level, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
          {
            System.Threading.Interlocked.Increment(ref Calls);
            return base.shade(level, importance, ref p0, ref p1, color);
          }
        }
      }
      """);
    string script = Write("Scene.cs", """
      Scenes.FiveBalls(scene);
      context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing(scene);
      context[PropertyName.CTX_WIDTH] = 20;
      context[PropertyName.CTX_HEIGHT] = 15;
      """);

    using var host = new ScriptHost();
    host.AddModule(scratch.Path);
    ScriptScene run = host.Load(script);
    Type type = run.Algorithm!.GetType();
    Assert.Equal("Rendering.DistributedRayTracing", type.FullName);
    Assert.NotEqual(typeof(Rendering.Distributed.DistributedRayTracing).Assembly, type.Assembly);
    TileRenderer.Render(run.Scene, (IImageFunction)run.Algorithm, new SimpleImageSynthesizer { Width = 20, Height = 15 }, new RenderOptions { Threads = 1 });
    Assert.True((int)type.GetField("Calls")!.GetValue(null)! >= 20 * 15);
  }

  [Fact]
  public void A_folder_of_scene_scripts_only_is_refused_with_a_message_saying_so()
  {
    Write("a.cs", "scene.BackgroundColor = new double[] { 1, 0, 0 };\n");
    using var host = new ScriptHost();
    var ex = Assert.Throws<ScriptCompilationException>(() => host.AddModule(scratch.Path));
    Assert.Contains("only scene scripts", ex.Message);
  }

  [Fact]
  public void Module_code_written_for_OpenTK_4_still_compiles()
  {
    Write("Four.cs", """
      using OpenTK.Mathematics;

      namespace Modern
      {
        public static class Mid
        {
          public static Vector3d Of (Vector3d a, Vector3d b) => (a + b) * 0.5;
        }
      }
      """);
    using var host = new ScriptHost();
    host.AddModule(scratch.Path);
    string script = Path.Combine(Path.GetTempPath(), $"grcis-mid-{Guid.NewGuid():N}.cs");
    File.WriteAllText(script, "context[\"mid\"] = Modern.Mid.Of(new Vector3d(0, 0, 0), new Vector3d(2, 4, 6));\n");
    try
    {
      Assert.Equal(new OpenTK.Mathematics.Vector3d(1, 2, 3), host.Load(script).Context["mid"]);
    }
    finally
    {
      File.Delete(script);
    }
  }

  [Fact]
  public void A_script_with_using_Scene3D_builds_a_mesh_with_SceneBrep()
  {
    string script = Write("mesh.cs", """
      using Scene3D;

      SceneBrep brep = new SceneBrep();
      int a = brep.AddVertex(new Vector3(0, 0, 0));
      int b = brep.AddVertex(new Vector3(1, 0, 0));
      int c = brep.AddVertex(new Vector3(0, 1, 0));
      brep.AddTriangle(a, b, c);
      context["triangles"] = brep.Triangles;
      """);
    using var host = new ScriptHost();
    Assert.Equal(1, host.Load(script).Context["triangles"]);
  }

  [Fact]
  public void Data_files_named_with_backslashes_relative_to_the_script_are_found()
  {
    Write("homework/models/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    string script = Write("homework/scene.cs", """
      using Scene3D;
      using System.IO;

      var reader = new WavefrontObj();
      var a = new SceneBrep();
      context["relative"] = reader.ReadBrep("models\\tri.obj", a);
      string dir = Path.GetDirectoryName((string)context[PropertyName.CTX_SCRIPT_PATH]);
      var b = new SceneBrep();
      context["combined"] = reader.ReadBrep(Path.Combine(dir, "models\\tri.obj"), b);
      """);
    Assert.NotEqual(Path.Combine(scratch.Path, "homework"), Directory.GetCurrentDirectory());
    using var host = new ScriptHost();
    ScriptScene run = host.Load(script);
    Assert.Equal(1, run.Context["relative"]);
    Assert.Equal(1, run.Context["combined"]);
  }
}
