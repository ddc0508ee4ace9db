using System.IO;
using System.Linq;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.ClassicScenes;

/// <summary>GrCis's mesh scenes ("Str" scenes): an OBJ model framed by the camera, or a sphere when the file is missing.</summary>
public class MeshScenesTests
{
  static string Teapot => SharedFolder.Combine("data", "meshes", "teapot.obj.gz");

  [Fact]
  public void The_teapot_scene_reads_the_mesh_and_frames_it()
  {
    var sc = new DefaultRayScene();
    long faces = Scenes.TeapotObj(sc, new[] { Teapot });
    Assert.InRange(faces, 6000, 7000);
    FloatImage image = TileRenderer.Render(sc, new RayTracing(sc), new SimpleImageSynthesizer { Width = 64, Height = 48 }, new RenderOptions());
    // The orange teapot fills the middle; the corner is the dark background.
    double[] middle = image.GetPixel(32, 24), corner = image.GetPixel(0, 0);
    Assert.True(middle[0] > middle[2] + 0.1, $"middle {string.Join(", ", middle)}");
    Assert.Equal(new[] { 0.0, 0.05, 0.07 }, corner.Select(v => System.Math.Round(v, 6)));
  }

  [Fact]
  public void A_missing_file_falls_back_to_a_sphere_and_a_bare_name_is_searched_for()
  {
    var sc = new DefaultRayScene();
    Assert.Equal(0, Scenes.PitcherObj(sc, new[] { Path.Combine("no", "such", "pitcher.obj") }));
    var root = Assert.IsType<CSGInnerNode>(sc.Intersectable);
    Assert.IsType<Sphere>(Assert.Single(root.Children));

    string?[] found = Scenes.SmartFindFiles(new[] { "", Path.Combine("a", "b.obj"), "no-such-file-anywhere.obj" })!;
    Assert.Equal("", found[0]);
    Assert.Equal(Path.Combine("a", "b.obj"), found[1]);
    Assert.Null(found[2]);
    Assert.Equal(4, Scenes.NamesStr.Length);
    Assert.IsType<InitSceneParamDelegate>(Scenes.staticRepository["Two spheres"]);
    Assert.IsType<InitSceneDelegate>(Scenes.staticRepository["Five balls"]);
  }
}
