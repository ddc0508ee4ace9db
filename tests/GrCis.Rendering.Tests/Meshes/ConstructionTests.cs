using System.IO;
using OpenTK.Mathematics;
using Scene3D;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>GrCis's mesh-construction template: a closed, outward-facing tetrahedron placed by a matrix.</summary>
public class ConstructionTests
{
  static SceneBrep Build(Matrix4 m)
  {
    var scene = new SceneBrep();
    Assert.Equal(4, new Construction().AddMesh(scene, m, ""));
    return scene;
  }

  [Fact]
  public void InitParams_gives_an_empty_parameter_and_an_author()
  {
    Construction.InitParams(out string param, out string name);
    Assert.Equal("", param);
    Assert.False(string.IsNullOrWhiteSpace(name));
  }

  [Fact]
  public void The_tetrahedron_is_closed_regular_and_faces_outward()
  {
    SceneBrep s = Build(Matrix4.Identity);
    Assert.Equal(4, s.Vertices);
    Assert.Equal(4, s.Triangles);
    s.BuildCornerTable();
    Assert.Equal(6, s.statShared);
    Assert.Equal(0, s.CheckCornerTable(new StreamWriter(Stream.Null), thorough: true));

    float edge = (s.GetVertex(0) - s.GetVertex(1)).Length;
    for (int a = 0; a < 4; a++)
    {
      for (int b = a + 1; b < 4; b++)
        Assert.Equal(edge, (s.GetVertex(a) - s.GetVertex(b)).Length, 4);
      Assert.Equal(s.GetVertex(a).Normalized(), s.GetNormal(a));
    }
    for (int t = 0; t < 4; t++)
    {
      s.GetTriangleVertices(t, out Vector3 p, out Vector3 q, out Vector3 r);
      Vector3 normal = Vector3.Cross(q - p, r - p);
      Assert.True(Vector3.Dot(normal, p + q + r) > 0f, $"triangle {t} faces inward");
    }
  }

  [Fact]
  public void The_matrix_places_the_shape_and_its_position_picks_the_colours()
  {
    SceneBrep home = Build(Matrix4.Identity);
    SceneBrep moved = Build(Matrix4.CreateTranslation(3f, 0f, -1f));
    for (int v = 0; v < 4; v++)
    {
      Vector3 d = moved.GetVertex(v) - home.GetVertex(v);
      Assert.Equal(new Vector3(3f, 0f, -1f), d);
      Assert.Equal(home.GetNormal(v), moved.GetNormal(v));
      Vector3 c = moved.GetColor(v);
      Assert.True(c.X is >= 0f and <= 1f && c.Y is >= 0f and <= 1f && c.Z is >= 0f and <= 1f);
    }
    Assert.NotEqual(home.GetColor(0), moved.GetColor(0));
    Assert.Equal(new Vector2(0f, 1f), home.GetTxtCoord(3));
  }
}
