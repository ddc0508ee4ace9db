using System.Linq;
using GrCis.Hosting;
using Rendering;
using Rendering.Tessellation;

namespace GrCis.Studio.Tests;

/// <summary>
/// The 3D view's triangle budget (<see cref="SceneView3d.TriangleBudget"/>): a scene within it is sent whole; beyond it
/// the largest shapes go as their boxes, with a note each, and the small solids around them stay surfaces.
/// </summary>
public class Scene3dBudgetTests
{
  static SceneTessellation TorusAndBalls()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new TriangleMesh(ProceduralMesh.Torus(64, 32)), Matrix4dOf(0.0));
    root.InsertChild(new Sphere(), Matrix4dOf(3.0));
    root.InsertChild(new Sphere(), Matrix4dOf(-3.0));
    return SceneTessellator.Tessellate(new DefaultRayScene { Intersectable = root, Camera = new StaticCamera() });
  }

  static OpenTK.Mathematics.Matrix4d Matrix4dOf(double x) => OpenTK.Mathematics.Matrix4d.CreateTranslation(x, 0.0, 0.0);

  [Fact]
  public void A_scene_within_the_budget_is_sent_whole()
  {
    SceneTessellation scene = TorusAndBalls();
    SceneView3d.SceneJson json = SceneView3d.Of(scene, new RenderSettings(), "torus");
    Assert.All(json.Parts, p => Assert.Equal("Surface", p.Kind));
    Assert.Equal(scene.Parts.GroupBy(p => p.Positions).Sum(g => g.First().TriangleCount), json.Shapes.Sum(s => s.Indices.Length / 3));
    Assert.Empty(json.Notes);
  }

  [Fact]
  public void Beyond_the_budget_the_largest_shape_is_sent_as_its_box_with_a_note()
  {
    SceneTessellation scene = TorusAndBalls();
    TessellatedPart torus = scene.Parts.Single(p => p.TypeName == nameof(TriangleMesh));
    TessellatedPart ball = scene.Parts.First(p => p.TypeName == nameof(Sphere));
    // Room for the spheres' one shared shape, not for the torus's 4096 triangles.
    SceneView3d.SceneJson json = SceneView3d.Of(scene, new RenderSettings(), "torus", triangleBudget: ball.TriangleCount + 100);

    SceneView3d.PartJson mesh = json.Parts.Single(p => p.Type == nameof(TriangleMesh));
    Assert.Equal("BoundingBox", mesh.Kind);
    SceneView3d.ShapeJson box = json.Shapes[mesh.Shape];
    Assert.Equal(12, box.Indices.Length / 3);
    Assert.Equal(24, box.Positions.Length);
    // The box holds every vertex of the torus (in its local space), and touches them on every side.
    for (int axis = 0; axis < 3; axis++)
    {
      float[] coords = Enumerable.Range(0, 8).Select(k => box.Positions[3 * k + axis]).ToArray();
      double lo = torus.Positions.Min(p => p[axis]), hi = torus.Positions.Max(p => p[axis]);
      Assert.Equal((float)lo, coords.Min());
      Assert.Equal((float)hi, coords.Max());
    }
    Assert.All(json.Parts.Where(p => p.Type == nameof(Sphere)), p => Assert.Equal("Surface", p.Kind));
    string note = Assert.Single(json.Notes);
    Assert.Contains(torus.Name, note);
    Assert.Contains($"{torus.TriangleCount:N0} triangles", note);
  }
}
