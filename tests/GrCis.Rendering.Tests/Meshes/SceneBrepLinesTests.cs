using System.IO;
using OpenTK.Mathematics;
using Scene3D;
using static GrCis.Rendering.Tests.Meshes.MeshTestSupport;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>GrCis's line mode of SceneBrep, random vertex colours and the corner-table check.</summary>
public class SceneBrepLinesTests
{
  static SceneBrep Polyline(int n)
  {
    var s = new SceneBrep();
    for (int i = 0; i < n; i++)
      s.AddVertex(new Vector3(i, i * i, 0));
    for (int i = 0; i + 1 < n; i++)
      s.AddLine(i, i + 1);
    return s;
  }

  [Fact]
  public void A_mesh_of_lines_takes_no_triangles()
  {
    var empty = new SceneBrep();
    Assert.True(empty.HasLines && empty.HasTriangles);

    SceneBrep s = Polyline(4);
    Assert.True(s.HasLines);
    Assert.False(s.HasTriangles);
    Assert.Equal(3, s.Lines);
    Assert.Equal(0, s.Triangles);
    Assert.Equal(0, s.Corners);
    Assert.Equal(SceneBrep.NULL, s.AddTriangle(0, 1, 2));
    s.GetLineVertices(2, out int a, out int b);
    Assert.Equal((2, 3), (a, b));
    Assert.Throws<System.ArgumentOutOfRangeException>(() => s.GetLineVertices(3, out _, out _));
    s.BuildCornerTable();
    Assert.Equal(SceneBrep.NULL, s.cOpposite(0));
    Assert.Equal(0, s.CheckCornerTable(new StreamWriter(Stream.Null)));
  }

  [Fact]
  public void A_mesh_of_triangles_takes_no_lines()
  {
    SceneBrep s = Read(CubeObj);
    Assert.Equal(SceneBrep.NULL, s.AddLine(0, 1));
    Assert.Equal(0, s.Lines);
    Assert.Equal(12, s.Triangles);
  }

  [Fact]
  public void Clone_and_Reset_keep_or_clear_the_line_mode()
  {
    SceneBrep s = Polyline(3);
    s.LineWidth = 5.0f;
    SceneBrep copy = s.Clone();
    Assert.Equal(2, copy.Lines);
    Assert.Equal(5.0f, copy.LineWidth);
    s.Reset();
    Assert.Equal(2.0f, s.LineWidth);
    Assert.True(s.HasTriangles);
  }

  [Fact]
  public void GenerateColors_is_reproducible_and_keeps_existing_colours()
  {
    SceneBrep a = Polyline(5), b = Polyline(5);
    a.GenerateColors(42);
    b.GenerateColors(42);
    Assert.Equal(5, a.Colors);
    for (int v = 0; v < 5; v++)
    {
      Assert.Equal(a.GetColor(v), b.GetColor(v));
      Vector3 c = a.GetColor(v);
      Assert.True(c.X is >= 0f and < 1f && c.Y is >= 0f and < 1f && c.Z is >= 0f and < 1f);
    }
    Assert.NotEqual(a.GetColor(0), a.GetColor(1));
    Vector3 before = a.GetColor(3);
    a.GenerateColors(7);
    Assert.Equal(before, a.GetColor(3));
  }

  [Fact]
  public void CheckCornerTable_passes_a_closed_cube_even_thoroughly()
  {
    SceneBrep s = Read(CubeObj);
    s.BuildCornerTable();
    var log = new MemoryStream();
    using var w = new StreamWriter(log) { AutoFlush = true };
    Assert.Equal(0, s.CheckCornerTable(w, thorough: true));
    Assert.Equal(0, log.Length);
  }

  [Fact]
  public void CheckCornerTable_reports_flipped_degenerate_and_unlinked_triangles()
  {
    var s = new SceneBrep();
    for (int i = 0; i < 4; i++)
      s.AddVertex(new Vector3(i & 1, i >> 1, 0));
    s.AddTriangle(0, 1, 2);
    s.AddTriangle(1, 2, 3);    // shares edge 1–2 facing the same way as the first: flipped
    s.AddTriangle(3, 3, 0);    // uses a vertex twice
    s.BuildCornerTable();
    var log = new MemoryStream();
    using (var w = new StreamWriter(log))
    {
      int problems = s.CheckCornerTable(w, thorough: true);
      Assert.True(problems >= 3, $"{problems} problems");
    }
    string text = System.Text.Encoding.UTF8.GetString(log.ToArray());
    Assert.Contains("face opposite ways", text);
    Assert.Contains("twice", text);
  }

  [Fact]
  public void CheckCornerTable_finds_links_the_table_lost()
  {
    SceneBrep s = Read(CubeObj);   // corner table not built: no corner is linked
    var log = new MemoryStream();
    using var w = new StreamWriter(log) { AutoFlush = true };
    Assert.Equal(18, s.CheckCornerTable(w, thorough: true));
    Assert.Contains("not linked", System.Text.Encoding.UTF8.GetString(log.ToArray()));
    Assert.Equal(0, s.CheckCornerTable(w));   // the quick check only looks at linked corners
  }
}
