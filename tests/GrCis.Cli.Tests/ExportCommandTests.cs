using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Numerics;
using GrCis.Cli.SceneSources;
using GrCis.Hosting;
using Rendering;
using SharpGLTF.Schema2;
using Vector3d = OpenTK.Mathematics.Vector3d;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis export</c>: every script and built-in scene becomes a glTF file that SharpGLTF reads back with a mesh node per
/// solid of the scene graph, the scene's camera (z mirrored into glTF's right-handed world) and its lights; bad output
/// names, unwritable places and broken scripts fail as the other commands fail, writing nothing.
/// </summary>
public class ExportCommandTests
{
  public static TheoryData<string> Scripts => new(Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(Path.GetFileName).Order()!);

  public static TheoryData<string> BuiltIns => new(SceneResolver.BuiltInNames);

  [Theory]
  [MemberData(nameof(Scripts))]
  public void Every_script_exports_a_node_per_solid_its_camera_and_its_lights(string script) =>
    AssertExport(RepoPaths.Script(script));

  [Theory]
  [MemberData(nameof(BuiltIns))]
  public void Every_built_in_scene_exports_a_node_per_solid_its_camera_and_its_lights(string name) => AssertExport(name);

  static void AssertExport(string scene, double? time = null)
  {
    using var dir = new TempDirectory();
    var args = new List<string> { "export", scene, "-o", "out.glb" };
    if (time is double t)
      args.AddRange(["--time", t.ToString(System.Globalization.CultureInfo.InvariantCulture)]);
    CliRun run = CliRun.Of(dir.Path, args.ToArray());
    Assert.True(run.ExitCode == 0, run.Error);
    Assert.Equal([dir.File("out.glb")], dir.AllFiles());

    // The same scene, built as a render builds it, is what the file must hold.
    ISceneSource source = new SceneResolver(dir.Path).Resolve(scene);
    using var host = source as IDisposable;
    PreparedRender prepared = new RenderRequest(source, new RenderSettings(), Time: time).Prepare();
    IRayScene expected = prepared.Scene;
    ModelRoot model = ModelRoot.Load(dir.File("out.glb"));

    Assert.Equal(Leaves(expected.Intersectable), model.LogicalNodes.Count(n => n.Mesh != null));
    Assert.All(model.LogicalNodes.Where(n => n.Mesh != null), n => Assert.True(n.Mesh.Primitives[0].GetTriangleIndices().Any(), n.Name));

    Node cameraNode = Assert.Single(model.LogicalNodes, n => n.Camera != null);
    Rendering.ICamera camera = expected.Camera!;
    camera.Width = prepared.Settings.Width;
    camera.Height = prepared.Settings.Height;
    camera.GetRay(0.5 * camera.Width, 0.5 * camera.Height, out Vector3d p0, out Vector3d p1);
    if (camera is StaticCamera pinhole)
      // A thin lens's ray starts at a sampled point of the lens: the pinhole's is its centre.
      (p0, p1) = (pinhole.center, pinhole.direction);
    Matrix4x4 world = cameraNode.WorldMatrix;
    AssertNear(Mirror(p0), world.Translation, 1e-4 * Math.Max(1.0, p0.Length));
    // A glTF camera looks along its −z.
    AssertNear(Mirror(p1.Normalized()), Vector3.Normalize(-new Vector3(world.M31, world.M32, world.M33)), 1e-4);

    List<Vector3d> lights = Lights(expected);
    Node[] lightNodes = model.LogicalNodes.Where(n => n.PunctualLight != null).ToArray();
    Assert.Equal(lights.Count, lightNodes.Length);
    for (int i = 0; i < lights.Count; i++)
      AssertNear(Mirror(lights[i]), lightNodes[i].WorldMatrix.Translation, 1e-4 * Math.Max(1.0, lights[i].Length));
  }

  /// <summary>The solids of the scene graph: its leaves below the root (or the root when it has no children).</summary>
  static int Leaves(IIntersectable? node) => node switch
  {
    null => 0,
    ISceneNode n when n.Children.Count > 0 => n.Children.Sum(Leaves),
    _ => 1,
  };

  /// <summary>Where each light with a place is: a point light's position, a rectangle light's centre.</summary>
  static List<Vector3d> Lights(IRayScene scene) =>
    (scene.Sources ?? []).Where(l => l.position != null)
      .Select(l => l is RectangleLightSource r ? r.position!.Value + 0.5 * (r.width + r.height) : l.position!.Value).ToList();

  static Vector3 Mirror(Vector3d v) => new((float)v.X, (float)v.Y, (float)-v.Z);

  static void AssertNear(Vector3 expected, Vector3 actual, double tolerance) =>
    Assert.True((expected - actual).Length() <= tolerance, $"expected {expected}, got {actual}");

  [Fact]
  public void An_animated_script_is_exported_at_the_time_given()
  {
    AssertExport(RepoPaths.Script("Orbit.cs"), time: 1.5);
    using var dir = new TempDirectory();
    Assert.Equal(0, CliRun.Of(dir.Path, "export", RepoPaths.Script("Orbit.cs"), "-o", "a.glb").ExitCode);
    Assert.Equal(0, CliRun.Of(dir.Path, "export", RepoPaths.Script("Orbit.cs"), "-o", "b.glb", "--time", "1.5").ExitCode);
    Vector3 Camera(string f) => ModelRoot.Load(dir.File(f)).LogicalNodes.Single(n => n.Camera != null).WorldMatrix.Translation;
    Assert.True((Camera("a.glb") - Camera("b.glb")).Length() > 0.1, "the orbiting camera did not move");
  }

  [Fact]
  public void A_gltf_file_is_json_with_its_bin_beside_it_and_nothing_else()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "export", "Five balls", "-o", "sub/balls.gltf");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal([dir.File("sub/balls.bin"), dir.File("sub/balls.gltf")], dir.AllFiles().Order());
    Assert.StartsWith("wrote " + dir.File("sub/balls.gltf"), run.Out);
    Assert.Contains("\"KHR_lights_punctual\"", File.ReadAllText(dir.File("sub/balls.gltf")));
    ModelRoot model = ModelRoot.Load(dir.File("sub/balls.gltf"));
    Assert.Equal(5, model.LogicalNodes.Count(n => n.Mesh != null));
    // Five unit spheres share one sphere's vertices: a mesh per colour, and one vertex buffer for all.
    Assert.Equal(model.LogicalMaterials.Count, model.LogicalMeshes.Count);
    Assert.Single(model.LogicalMeshes.Select(m => m.Primitives[0].GetVertexAccessor("POSITION")).Distinct());
  }

  [Fact]
  public void Without_o_the_file_is_named_after_the_scene()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "export", "Two spheres", "-q");

    Assert.Equal(0, run.ExitCode);
    Assert.Equal("", run.Out);
    Assert.Equal([dir.File("two-spheres.glb")], dir.AllFiles());
  }

  [Theory]
  [InlineData("scene.obj", "cannot export to '.obj' files")]
  [InlineData("scene", "has no extension")]
  [InlineData("scene.png", "use .glb (binary glTF) or .gltf")]
  public void Another_extension_is_a_usage_error_and_nothing_is_written(string output, string message)
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "export", "Five balls", "-o", output);

    Assert.Equal(2, run.ExitCode);
    Assert.Contains(message, run.Error);
    Assert.StartsWith("grcis: error: ", run.Error);
    Assert.Empty(dir.AllFiles());
  }

  [Fact]
  public void An_unwritable_output_fails_with_its_path_and_writes_nothing()
  {
    using var dir = new TempDirectory();
    File.WriteAllText(dir.File("blocker"), "a file where a folder should be");
    CliRun run = CliRun.Of(dir.Path, "export", "Five balls", "-o", "blocker/scene.glb");

    Assert.Equal(1, run.ExitCode);
    Assert.Equal($"grcis: error: cannot write '{dir.File("blocker/scene.glb")}': '{dir.File("blocker")}' is a file, not a directory", run.ErrorLines.Single());
    Assert.Equal([dir.File("blocker")], dir.AllFiles());
  }

  [Fact]
  public void A_script_that_does_not_compile_names_its_file_and_line_and_writes_nothing()
  {
    using var dir = new TempDirectory();
    string script = dir.File("broken.cs");
    File.WriteAllText(script, "scene.Intersectable = new Sphere();\nint n = \"three\";\n");
    CliRun run = CliRun.Of(dir.Path, "export", script, "-o", "out.glb");

    Assert.Equal(1, run.ExitCode);
    Assert.Contains(run.ErrorLines, l => l.StartsWith($"{script}(2,9): error CS0029:", StringComparison.Ordinal));
    Assert.Equal([script], dir.AllFiles());
  }

  [Fact]
  public void A_mistyped_option_is_suggested()
  {
    using var dir = new TempDirectory();
    CliRun run = CliRun.Of(dir.Path, "export", "Five balls", "--tim", "2");

    Assert.Equal(2, run.ExitCode);
    Assert.Contains("--time", run.Error);
    Assert.Empty(dir.AllFiles());
  }
}
