using System.IO;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// A scene script from a student's fork of GrCis names its data for Windows GrCis's working folder
/// (<c>&lt;project&gt;/bin/Debug</c>), with backslashes and in whatever letter case: it runs unchanged from where it lies.
/// </summary>
public sealed class ForkDataPathsTests : System.IDisposable
{
  readonly ScratchFolder fork = new("grcis-fork-");

  public ForkDataPathsTests()
  {
    fork.Write("data/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    fork.Write("data/rtscenes/params.txt", "n=1.5");
    var image = new Rgb8Image(2, 1);
    image.SetPixel(0, 0, 255, 0, 0);
    image.SetPixel(1, 0, 0, 0, 255);
    Directory.CreateDirectory(Path.Combine(fork.Path, "048rtmontecarlo-script", "Textures"));
    PngFile.Save(Path.Combine(fork.Path, "048rtmontecarlo-script", "Textures", "Stripes.png"), image);
  }

  public void Dispose() => fork.Dispose();

  const string Body = """
    using Scene3D;

    // As written in 2019 for 048rtmontecarlo-script\bin\Debug.
    SceneBrep brep = new SceneBrep();
    context["triangles"] = new WavefrontObj().ReadBrep("..\\..\\..\\data\\Meshes\\Tri.OBJ", brep);
    string text;
    context["read"] = Util.ReadTextFile("..\\..\\..\\data\\rtscenes\\Params.txt", out text) ? text : null;
    ImageTexture tex = new ImageTexture("..\\..\\textures\\stripes.png");
    context["width"] = tex.Image.Width;
    scene.Intersectable = new TriangleMesh(brep);
    """;

  [Theory]
  [InlineData("data/rtscenes/Scene.cs")]
  [InlineData("048rtmontecarlo-script/Scene.cs")]
  public void Mesh_text_and_texture_paths_for_bin_Debug_are_found_from_the_script(string where)
  {
    string script = fork.Write(where, Body);
    using var host = new ScriptHost();
    ScriptScene run = host.Load(script);
    Assert.Equal(1, run.Context["triangles"]);
    Assert.Equal("n=1.5", run.Context["read"]);
    Assert.Equal(2, run.Context["width"]);
  }

  [Fact]
  public void A_file_that_is_nowhere_names_what_the_script_wrote()
  {
    string script = fork.Write("data/rtscenes/Missing.cs", """
      using Scene3D;
      new WavefrontObj().ReadBrep("..\\..\\..\\data\\meshes\\none.obj", new SceneBrep());
      """);
    using var host = new ScriptHost();
    var e = Assert.Throws<ScriptRuntimeException>(() => host.Load(script));
    Assert.Contains("none.obj", e.Message);
  }
}
