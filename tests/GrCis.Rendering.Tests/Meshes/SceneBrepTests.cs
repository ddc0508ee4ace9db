using Scene3D;
using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Meshes.MeshTestSupport;

namespace GrCis.Rendering.Tests.Meshes;

public class SceneBrepTests
{
  [Fact]
  public void SceneBrep_counts_vertices_triangles_and_attributes()
  {
    var s = new SceneBrep();
    int a = s.AddVertex(new Vector3(0, 0, 0));
    int b = s.AddVertex(new Vector3(1, 0, 0));
    int c = s.AddVertex(new Vector3(0, 1, 0));
    Assert.Equal(0, s.AddTriangle(a, b, c));
    Assert.Equal(3, s.Vertices);
    Assert.Equal(1, s.Triangles);
    Assert.Equal(3, s.Corners);
    Assert.False(s.HasNormals());
    s.SetNormal(b, new Vector3(0, 0, 1));
    Assert.Equal(3, s.Normals);
    s.SetTxtCoord(c, new Vector2(0.5f, 1));
    Assert.Equal(new Vector2(0.5f, 1), s.GetTxtCoord(c));
    Assert.Equal(3, s.TxtCoords);
    int d = s.AddVertex(new Vector3(1, 1, 0));   // attributes grow with the vertices
    Assert.Equal(4, s.Normals);
    Assert.Equal(4, s.TxtCoords);
    Assert.Equal(3, d);
  }

  [Fact]
  public void SceneBrep_compute_normals_points_outward_on_a_closed_cube()
  {
    SceneBrep s = Read(CubeObj);
    s.ComputeNormals();
    // Vertex (1,1,1) averages three face normals: the diagonal direction.
    Vector3 n = s.GetNormal(6);
    float k = 1f / System.MathF.Sqrt(3);
    Assert.Equal(k, n.X, 5);
    Assert.Equal(k, n.Y, 5);
    Assert.Equal(k, n.Z, 5);
  }

  [Fact]
  public void SceneBrep_corner_table_links_every_edge_of_a_closed_cube()
  {
    SceneBrep s = Read(CubeObj);
    s.BuildCornerTable();
    Assert.Equal(18, s.statShared);
    for (int c = 0; c < s.Corners; c++)
    {
      int o = s.cOpposite(c);
      Assert.NotEqual(SceneBrep.NULL, o);
      Assert.Equal(c, s.cOpposite(o));
      // The opposite corner sees the same edge, reversed.
      Assert.Equal(s.cVertex(SceneBrep.cNext(c)), s.cVertex(SceneBrep.cPrev(o)));
    }
  }

  [Fact]
  public void SceneBrep_invalid_handles_throw()
  {
    var s = new SceneBrep();
    Assert.Throws<System.ArgumentOutOfRangeException>(() => s.AddTriangle(0, 1, 2));
  }
}
