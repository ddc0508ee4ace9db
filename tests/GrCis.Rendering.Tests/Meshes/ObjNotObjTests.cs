using Scene3D;
using System;
using System.IO;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>What the OBJ reader makes of files that are empty, have no faces, or are no OBJ at all.</summary>
public class ObjNotObjTests
{
  static MeshFormatException Fails(string text) =>
    Assert.Throws<MeshFormatException>(() => new WavefrontObj().ReadBrep(new StringReader(text), new SceneBrep(), Matrix4d.Identity, "thing.obj"));

  [Theory]
  [InlineData("")]
  [InlineData("\n\n# only comments\n")]
  [InlineData("g nothing\nusemtl none\n")]
  [InlineData("v 0 0 0\nv 1 0 0\n")]
  public void An_obj_without_faces_is_an_empty_mesh(string text)
  {
    SceneBrep s = MeshTestSupport.Read(text);
    Assert.Equal(0, s.Triangles);
  }

  [Fact]
  public void Unknown_statements_among_obj_statements_are_skipped()
  {
    SceneBrep s = MeshTestSupport.Read("vc 1 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nmadeup 7\nf 1 2 3\n");
    Assert.Equal(1, s.Triangles);
  }

  [Fact]
  public void A_text_without_any_obj_statement_is_not_an_obj_file_at_its_first_line()
  {
    MeshFormatException e = Fails("\n# a scene description\nscene:\n  camera: [0, 0, -5]\n");
    Assert.Equal(3, e.LineNumber);
    Assert.StartsWith("thing.obj(3): 'scene:' is not an OBJ statement", e.Message);
    Assert.Contains("not a Wavefront OBJ file", e.Message);
  }

  [Fact]
  public void A_ply_file_read_as_obj_is_not_an_obj_file()
  {
    MeshFormatException e = Fails("ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
    Assert.Equal(1, e.LineNumber);
    Assert.Contains("'ply'", e.Message);
  }

  [Fact]
  public void Binary_data_is_not_an_obj_file_at_the_line_where_it_is_found()
  {
    MeshFormatException e = Fails("v 0 0 0\nv 1 0\u0001 0\n");
    Assert.Equal(2, e.LineNumber);
    Assert.Equal("thing.obj(2): binary data (character 0x01): not a Wavefront OBJ text file", e.Message);
  }

  [Fact]
  public void A_file_of_random_bytes_is_an_error_naming_the_file()
  {
    string path = Path.Combine(Path.GetTempPath(), $"grcis-noise-{Guid.NewGuid():N}.obj");
    var bytes = new byte[4096];
    new Random(29).NextBytes(bytes);
    File.WriteAllBytes(path, bytes);
    try
    {
      var e = Assert.Throws<MeshFormatException>(() => new WavefrontObj().ReadBrep(path, new SceneBrep()));
      Assert.Equal(path, e.FileName);
      Assert.StartsWith(path + "(", e.Message);
      Assert.Contains("not a Wavefront OBJ", e.Message);
    }
    finally
    {
      File.Delete(path);
    }
  }

  [Fact]
  public void Dos_end_of_file_marks_and_form_feeds_are_text()
  {
    SceneBrep s = MeshTestSupport.Read("v 0 0 0\f\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\u001A");
    Assert.Equal(1, s.Triangles);
  }
}
