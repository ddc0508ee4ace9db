using System.IO;
using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Scripting.Tests;

/// <summary>Scripts written in the GrCis style run unchanged.</summary>
public class DialectTests
{
  readonly ScriptHost host = new();

  [Fact]
  public void Script_method_and_classes_declared_after_use_build_the_scene()
  {
    ScriptScene result = host.Load(TestData.Script("ClassesAndMethods.cs"));
    IRayScene scene = result.Scene;

    // Classes declared below the statements that use them.
    Assert.Equal("FisheyeCamera", scene.Camera!.GetType().Name);
    ILightSource light = Assert.Single(scene.Sources!);
    Assert.Equal("ConstantLight", light.GetType().Name);
    Assert.IsType<LinkedList<ILightSource>>(scene.Sources);

    // The script's camera works: the image centre looks along +z, the corner is outside the fisheye disc.
    Assert.True(scene.Camera.GetRay(200, 200, out Vector3d p0, out Vector3d p1));
    Assert.Equal(new Vector3d(0, 0, -5), p0);
    Assert.Equal(1.0, p1.Z, 12);
    Assert.False(scene.Camera.GetRay(0, 0, out _, out _));

    // The method declared in the script made three coloured children.
    var root = Assert.IsType<CSGInnerNode>(scene.Intersectable);
    Assert.Equal(3, root.Children.Count);
    double[] color = (double[])root.Children.Last().GetAttribute(PropertyName.COLOR)!;
    Assert.Equal(new[] { 0.2, 0.5, 0.8 }, color, new Tolerance(1e-12));

    // OpenTK 3 style transform: S(0.5) * RX(pi/2) * T(2i, 0, 0).
    // MathHelper.PiOver2 is single precision, as in OpenTK (GrCis scenes depend on it).
    Matrix4d expected = Matrix4d.Scale(0.5) * Matrix4d.CreateRotationX(MathHelper.PiOver2) * Matrix4d.CreateTranslation(4.0, 0.0, 0.0);
    Assert.Equal(expected, root.Children.Last().ToParent);

    // The texture subclass declared in the script.
    var texture = (ITexture)root.Children.Last().GetAttribute(PropertyName.TEXTURE)!;
    Assert.Equal("HashStripes", texture.GetType().Name);
    var hit = new Intersection { TextureCoord = new Vector2d(0.3, 0.0), SurfaceColor = new[] { 0.0, 0.0, 0.0 } };
    texture.Apply(hit);
    Assert.Equal(new[] { 1.0, 1.0, 1.0 }, hit.SurfaceColor);

    // Fully qualified MathSupport.RandomStatic.numericRecipes.
    Assert.Equal((12345L * 1664525L + 1013904223L) & 0xFFFFFFFFL, (long)result.Context["hash"]);
  }

  [Fact]
  public void Preprocessing_call_runs_once_and_its_result_reaches_the_regular_call()
  {
    ScriptScene result = host.Load(TestData.Script("Preprocessing.cs"));

    Assert.True(result.Preprocessed);
    Assert.Equal(1, result.Context["preprocessCalls"]);
    Assert.Equal(3, result.Context["regularSawSimulation"]);
    Assert.False(result.Context.ContainsKey(PropertyName.CTX_PREPROCESSING));

    // The top-level 'return;' stopped the script before the red background.
    Assert.Equal(new[] { 0.1, 0.2, 0.3 }, result.Scene.BackgroundColor);
  }

  [Fact]
  public void Context_overrides_are_exposed_as_settings()
  {
    ScriptScene result = host.Load(TestData.Script("Preprocessing.cs"));
    Assert.Equal(320, result.Width);
    Assert.Equal(240, result.Height);
    Assert.Equal(4, result.SuperSampling);
    Assert.Equal(0.0, result.Start);
    Assert.Equal(5.0, result.End);
    Assert.Equal(30.0, result.Fps);
    Assert.Null(result.Time);
    Assert.Null(result.Algorithm);
    Assert.Null(result.Synthesizer);
    Assert.Equal("n=<double> (index of refraction)", result.ToolTip);
  }

  [Fact]
  public void A_context_of_two_or_more_entries_skips_preprocessing()
  {
    CompiledScript script = host.Compile(TestData.Script("Preprocessing.cs"));
    ScriptScene first = host.Run(script);

    // Later calls of the same batch reuse the context: no second preprocessing.
    ScriptScene second = host.Run(script, context: first.Context);
    Assert.False(second.Preprocessed);
    Assert.Equal(1, second.Context["preprocessCalls"]);
    Assert.NotSame(first.Scene, second.Scene);
  }

  [Fact]
  public void Script_without_preprocessing_block_in_a_fresh_context_sees_a_false_flag_afterwards()
  {
    var ctx = new Dictionary<string, object>();
    ScriptScene r = host.Load(TestData.Script("TimeDependent.cs"), context: ctx);
    Assert.Same(ctx, r.Context);
    Assert.Same(r.Scene, ctx[PropertyName.CTX_SCENE]);
    Assert.Equal(System.IO.Path.GetFullPath(TestData.Script("TimeDependent.cs")), ctx[PropertyName.CTX_SCRIPT_PATH]);
  }

  [Fact]
  public void Scene_is_ITimeDependent_pattern_matches_an_animated_scene()
  {
    CompiledScript script = host.Compile(TestData.Script("TimeDependent.cs"));

    var animated = new AnimatedTestScene();
    ScriptScene a = host.Run(script, scene: animated);
    Assert.Equal(true, a.Context["animated"]);
    Assert.Equal(1.0, animated.Start);
    Assert.Equal(9.0, animated.End);

    ScriptScene still = host.Run(script);
    Assert.Equal(false, still.Context["animated"]);
  }

  [Fact]
  public void Lambda_assigned_to_RecursionFunction_produces_RayRecursion()
  {
    ScriptScene result = host.Load(TestData.Script("Recursion.cs"));
    var root = Assert.IsType<CSGInnerNode>(result.Scene.Intersectable);
    ISceneNode glow = Assert.Single(root.Children);
    var fn = Assert.IsType<RecursionFunction>(glow.GetAttribute(PropertyName.RECURSION));

    var hit = new Intersection { Normal = new Vector3d(0, 0, -1), CoordWorld = new Vector3d(1, 2, 3) };
    long hash = fn(hit, new Vector3d(0, 0, 1), 0.5, out RayRecursion rr);

    Assert.Equal(144L, hash);
    Assert.Equal(new[] { 0.25, 0.25, 0.25 }, rr.DirectContribution);
    RayRecursion.RayContribution ray = Assert.Single(rr.Rays!);
    // GrCis starts the ray just off the surface, along its direction.
    Assert.Equal(new Vector3d(1, 2, 3) + Intersection.RAY_EPSILON * new Vector3d(0, 0, 1), ray.origin);
    Assert.Equal(ray.origin, ray.p0);
    Assert.Equal(0.5, ray.importance);
    Assert.Equal(true, glow.GetAttribute(PropertyName.NO_SHADOW));
  }

  [Fact]
  public void Param_string_is_parsed_with_Util()
  {
    ScriptScene result = host.Load(TestData.Script("Params.cs"), "n=1.5, depth=3, mat=glass, rc");
    Assert.Equal(1.5, result.Context["n"]);
    Assert.Equal(true, result.Context["nOk"]);
    Assert.Equal(3, result.Context["depth"]);
    Assert.Equal("glass", result.Context["mat"]);
    Assert.Equal(true, result.Context["rc"]);
    Assert.StartsWith("n=<double>", result.ToolTip);
  }

  [Fact]
  public void Bad_param_value_makes_Util_TryParse_return_false_and_keep_the_default()
  {
    ScriptScene result = host.Load(TestData.Script("Params.cs"), "n=abc");
    Assert.Equal(false, result.Context["nOk"]);
    Assert.Equal(1.6, result.Context["n"]);
    Assert.Equal(5, result.Context["depth"]);
    Assert.Equal(false, result.Context["rc"]);
  }

  [Fact]
  public void Null_param_is_an_empty_parameter_list()
  {
    ScriptScene result = host.Load(TestData.Script("Params.cs"), null);
    Assert.Equal(false, result.Context["nOk"]);
    Assert.Equal("diffuse", result.Context["mat"]);
  }

  [Fact]
  public void Using_OpenTK_is_harmless_and_extra_usings_work()
  {
    ScriptScene result = host.Load(TestData.Script("UsingOpenTK.cs"));
    Assert.Equal(7.0, result.Context["sum"]);
  }

  [Fact]
  public void Default_imports_are_GrCis_namespaces()
  {
    Assert.Equal(
      new[] { "System", "System.Diagnostics", "System.Collections.Generic", "OpenTK.Mathematics", "MathSupport", "Rendering", "Utilities", "Scene3D" },
      ScriptHost.DefaultImports);
  }

  [Fact]
  public void A_script_without_modules_uses_the_librarys_DistributedRayTracing()
  {
    string path = Path.Combine(Path.GetTempPath(), $"grcis-dist-{Guid.NewGuid():N}.cs");
    File.WriteAllText(path, "Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing(scene) { GlossyReflections = false };\n");
    try
    {
      ScriptScene result = host.Load(path);
      Assert.IsType<Rendering.Distributed.DistributedRayTracing>(result.Algorithm);
    }
    finally
    {
      File.Delete(path);
    }
  }

  sealed class Tolerance : IEqualityComparer<double>
  {
    readonly double eps;

    public Tolerance(double eps) => this.eps = eps;

    public bool Equals(double x, double y) => Math.Abs(x - y) <= eps;

    public int GetHashCode(double obj) => 0;
  }
}

/// <summary>A scene that is also time dependent, as AnimatedRayScene will be.</summary>
public sealed class AnimatedTestScene : DefaultRayScene, ITimeDependent
{
  public double Start { get; set; }
  public double End { get; set; }
  public double Time { get; set; }
  public object Clone() => MemberwiseClone();
}
