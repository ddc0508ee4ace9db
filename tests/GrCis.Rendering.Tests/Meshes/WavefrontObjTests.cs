using Scene3D;
using System;
using System.IO;
using System.IO.Compression;
using OpenTK.Mathematics;
using Rendering;
using static GrCis.Rendering.Tests.Meshes.MeshTestSupport;

namespace GrCis.Rendering.Tests.Meshes;

public class WavefrontObjTests
{
  [Fact]
  public void Obj_reads_all_face_corner_forms()
  {
    const string obj = @"
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
vt 0 0
vt 1 0
vt 0 1
vn 0 0 1
f 1 2 3
f 1/1 2/2 3/3
f 1//1 2//1 3//1
f 1/1/1 2/2/1 3/3/1
";
    SceneBrep s = Read(obj);
    Assert.Equal(4, s.Triangles);
    Assert.Equal(4, s.Vertices);   // consistent attributes: no duplicates
    Assert.Equal(4, s.Normals);
    Assert.Equal(4, s.TxtCoords);
    Assert.Equal(new Vector2(1, 0), s.GetTxtCoord(1));
    Assert.Equal(new Vector3(0, 0, 1), s.GetNormal(2));
  }

  [Fact]
  public void Obj_negative_indices_are_relative_to_the_last_element()
  {
    const string obj = @"
v 0 0 0
v 1 0 0
v 0 1 0
vn 0 0 1
f -3//-1 -2//-1 -1//-1
v 5 5 5
f -4 -1 -2
";
    SceneBrep s = Read(obj);
    Assert.Equal(2, s.Triangles);
    s.GetTriangleVertices(1, out int a, out int b, out int c);
    Assert.Equal((0, 3, 2), (a, b, c));
    Assert.Equal(new Vector3(5, 5, 5), s.GetVertex(b));
  }

  [Fact]
  public void Obj_polygons_are_fan_triangulated()
  {
    const string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 1 0\nf 1 2 3 4\nf 1 2 3 4 5\n";
    SceneBrep s = Read(obj);
    Assert.Equal(2 + 3, s.Triangles);
    s.GetTriangleVertices(1, out int a, out int b, out int c);
    Assert.Equal((0, 2, 3), (a, b, c));
    s.GetTriangleVertices(4, out a, out b, out c);
    Assert.Equal((0, 3, 4), (a, b, c));
  }

  [Fact]
  public void Obj_ignores_comments_and_unknown_statements()
  {
    const string obj = "mtllib x.mtl\n# comment\no thing\ng group\ns 1\nusemtl red\nv 0 0 0 # trailing\nv 1 0 0\nv 0 1 0\n\n   \nf 1 2 3\nl 1 2\n";
    SceneBrep s = Read(obj);
    Assert.Equal(1, s.Triangles);
    Assert.Equal(3, s.Vertices);
  }

  [Fact]
  public void Obj_position_used_with_different_normals_is_duplicated()
  {
    const string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 1 0\nf 1//1 2//1 3//1\nf 1//2 4//2 2//2\n";
    SceneBrep s = Read(obj);
    Assert.Equal(6, s.Vertices);   // vertices 1 and 2 get copies with the second normal
    s.GetTriangleVertices(1, out int a, out _, out int c);
    Assert.Equal(s.GetVertex(0), s.GetVertex(a));
    Assert.NotEqual(0, a);
    Assert.Equal(new Vector3(0, 1, 0), s.GetNormal(a));
    Assert.Equal(new Vector3(0, 0, 1), s.GetNormal(0));
    Assert.Equal(s.GetVertex(1), s.GetVertex(c));
  }

  [Fact]
  public void Obj_mirror_and_upside_down_options()
  {
    var r = new WavefrontObj { MirrorConversion = true, TextureUpsideDown = true };
    SceneBrep s = Read("v 1 2 3\nv 0 0 0\nv 1 0 0\nvt 0.25 0.25\nf 1/1 2/1 3/1\n", r);
    Assert.Equal(new Vector3(1, 2, -3), s.GetVertex(0));
    Assert.Equal(new Vector2(0.25f, 0.75f), s.GetTxtCoord(0));
  }

  [Theory]
  [InlineData("v 1 2", 3, "'v' needs more numbers")]
  [InlineData("v 1 x 3", 3, "'x' is not a number")]
  [InlineData("vn 1 2", 3, "'vn' needs more numbers")]
  [InlineData("f 1 2", 3, "at least 3 vertices")]
  [InlineData("f 1 2 7", 3, "vertex index 7 out of range")]
  [InlineData("f 1 2 0", 3, "vertex index 0 out of range")]
  [InlineData("f 1 2 -5", 3, "vertex index -5 out of range")]
  [InlineData("f 1 2 a", 3, "malformed vertex index 'a'")]
  [InlineData("f 1/5 2 3", 3, "texture coordinate index 5 out of range")]
  [InlineData("f 1//2 2 3", 3, "normal index 2 out of range")]
  [InlineData("f 1// 2 3", 3, "malformed face corner")]
  public void Obj_malformed_line_reports_file_and_line(string bad, int expectedLine, string fragment)
  {
    string obj = "v 0 0 0\nv 1 0 0\n" + bad + "\nv 0 1 0\n";
    var ex = Assert.Throws<MeshFormatException>(() => new WavefrontObj().ReadBrep(new StringReader(obj), new SceneBrep(), Matrix4d.Identity, "mesh.obj"));
    Assert.Equal(expectedLine, ex.LineNumber);
    Assert.Equal("mesh.obj", ex.FileName);
    Assert.StartsWith($"mesh.obj({expectedLine}): ", ex.Message);
    Assert.Contains(fragment, ex.Message);
    Assert.IsAssignableFrom<FormatException>(ex);
  }

  [Fact]
  public void Obj_error_in_a_gz_file_names_the_path_and_line()
  {
    string path = Path.Combine(Path.GetTempPath(), $"grcis-bad-{Guid.NewGuid():N}.obj.gz");
    try
    {
      using (var gz = new GZipStream(File.Create(path), CompressionLevel.Fastest))
      using (var w = new StreamWriter(gz))
        w.Write("# header\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 2 4\n");
      var ex = Assert.Throws<MeshFormatException>(() => new WavefrontObj().ReadBrep(path, new SceneBrep()));
      Assert.Equal(7, ex.LineNumber);
      Assert.StartsWith($"{path}(7): vertex index 4 out of range", ex.Message);
    }
    finally
    {
      File.Delete(path);
    }
  }

  [Theory]
  [InlineData("teapot.obj.gz", 6320)]
  [InlineData("pitcher.obj.gz", 9000 + 2 * 8211)]
  [InlineData("toyplane.obj.gz", 36264 + 2 * 9635)]
  [InlineData("buddha.obj.gz", 100000)]
  public void Obj_reads_the_shared_gz_meshes(string file, int triangles)
  {
    string path = Path.Combine(MeshDir, file);
    Assert.True(File.Exists(path), $"missing shared mesh {path}");
    var scene = new SceneBrep();
    int faces = new WavefrontObj().ReadBrep(path, scene);
    Assert.Equal(triangles, faces);
    Assert.Equal(triangles, scene.Triangles);
    Assert.True(scene.Vertices > 0);
    float diameter = scene.GetDiameter(out _);
    Assert.True(diameter > 0 && float.IsFinite(diameter));
  }

  [Fact]
  public void Obj_teapot_has_normals_and_the_expected_vertex_count()
  {
    var scene = new SceneBrep();
    new WavefrontObj().ReadBrep(Path.Combine(MeshDir, "teapot.obj.gz"), scene);
    Assert.Equal(6320, scene.Triangles);
    Assert.True(scene.Vertices >= 3240);
    Assert.Equal(scene.Vertices, scene.Normals);
  }

  [Fact]
  public void Obj_write_then_read_round_trips()
  {
    SceneBrep s = Read(CubeObj);
    s.ComputeNormals();
    var sw = new StringWriter();
    new WavefrontObj().WriteBrep(sw, s);
    SceneBrep back = Read(sw.ToString());
    Assert.Equal(s.Triangles, back.Triangles);
    Assert.Equal(s.Vertices, back.Vertices);
    Assert.Equal(s.GetNormal(6), back.GetNormal(6));
  }

  [Fact]
  public void Obj_error_quotes_a_huge_token_cut_to_forty_characters()
  {
    string number = new('7', 5_000_000);
    var e = Assert.Throws<MeshFormatException>(() => Read($"v 0 0 0\nv 1 x{number} 0\n"));
    Assert.Equal($"(stream)(2): 'x{new string('7', 39)}…' is not a number (in 'v')", e.Message);
    e = Assert.Throws<MeshFormatException>(() => Read($"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/{number}\n"));
    Assert.True(e.Message.Length < 200, e.Message.Length.ToString());
  }
}
