using System;
using System.IO;
using System.IO.Compression;
using System.Text;
using OpenTK.Mathematics;
using Rendering;
using Scene3D;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>PLY meshes in every encoding, written and read back, and broken files as file(line) errors.</summary>
public sealed class StanfordPlyTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-ply-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  string Write(string name, string text)
  {
    string path = Path.Combine(dir, name);
    File.WriteAllText(path, text);
    return path;
  }

  const string Quad = """
    ply
    format ascii 1.0
    comment a unit quad with normals and 8-bit colours
    element vertex 4
    property float x
    property float y
    property float z
    property float nx
    property float ny
    property float nz
    property uchar red
    property uchar green
    property uchar blue
    property float confidence
    element face 1
    property list uchar int vertex_indices
    end_header
    0 0 0  0 0 1  255 0 0  0.5
    1 0 0  0 0 1  0 255 0  0.5
    1 1 0  0 0 1  0 0 255  0.5
    0 1 0  0 0 1  255 255 255  0.5
    4 0 1 2 3
    """;

  [Fact]
  public void Ascii_quad_with_normals_and_byte_colours_becomes_two_triangles()
  {
    var brep = new SceneBrep();
    Assert.Equal(2, new StanfordPly().ReadBrep(Write("quad.ply", Quad), brep));
    Assert.Equal(4, brep.Vertices);
    Assert.Equal(new Vector3(1, 1, 0), brep.GetVertex(2));
    Assert.Equal(new Vector3(0, 0, 1), brep.GetNormal(3));
    Assert.Equal(new Vector3(0, 1, 0), brep.GetColor(1));
    brep.GetTriangleVertices(1, out int a, out int b, out int c);
    Assert.Equal((0, 2, 3), (a, b, c));
  }

  [Theory]
  [InlineData(true)]
  [InlineData(false)]
  public void Written_meshes_read_back_the_same_in_ascii_and_binary(bool text)
  {
    var brep = new SceneBrep();
    for (int i = 0; i < 5; i++)
    {
      int v = brep.AddVertex(new Vector3(i, i * 0.5f, -i));
      brep.SetNormal(v, new Vector3(0, 1, 0));
      brep.SetTxtCoord(v, new Vector2(i / 4f, 1 - i / 4f));
      brep.SetColor(v, new Vector3(0.25f, 0.5f, i / 5f));
    }
    brep.AddTriangle(0, 1, 2);
    brep.AddTriangle(2, 3, 4);
    string path = Path.Combine(dir, text ? "a.ply" : "b.ply");
    using (var w = new StreamWriter(path))
      new StanfordPly { TextFormat = text }.WriteBrep(w, brep);

    var back = new SceneBrep();
    Assert.Equal(2, new StanfordPly().ReadBrep(path, back));
    Assert.Equal(brep.Vertices, back.Vertices);
    for (int i = 0; i < brep.Vertices; i++)
    {
      Assert.Equal(brep.GetVertex(i), back.GetVertex(i));
      Assert.Equal(brep.GetNormal(i), back.GetNormal(i));
      Assert.Equal(brep.GetTxtCoord(i), back.GetTxtCoord(i));
      Assert.Equal(brep.GetColor(i), back.GetColor(i));
    }
    back.GetTriangleVertices(1, out int a, out int b, out int c);
    Assert.Equal((2, 3, 4), (a, b, c));
  }

  [Fact]
  public void Big_endian_binary_and_gzip_are_read()
  {
    var bytes = new MemoryStream();
    bytes.Write(Encoding.ASCII.GetBytes("ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n"));
    void BigEndian(byte[] b) { Array.Reverse(b); bytes.Write(b); }
    foreach (double v in new double[] { 0, 0, 0, 2, 0, 0, 0, 3, 0 })
      BigEndian(BitConverter.GetBytes(v));
    bytes.WriteByte(3);
    foreach (uint i in new uint[] { 0, 1, 2 })
      BigEndian(BitConverter.GetBytes(i));
    string gz = Path.Combine(dir, "tri.ply.gz");
    using (var file = File.Create(gz))
    using (var zip = new GZipStream(file, CompressionLevel.Fastest))
      zip.Write(bytes.ToArray());

    var brep = new SceneBrep();
    Assert.Equal(1, new StanfordPly().ReadBrep(gz, brep));
    Assert.Equal(new Vector3(0, 3, 0), brep.GetVertex(2));
  }

  [Fact]
  public void Orientation_swaps_y_and_z_and_the_winding()
  {
    var brep = new SceneBrep();
    new StanfordPly { Orientation = true }.ReadBrep(Write("quad.ply", Quad), brep);
    Assert.Equal(new Vector3(1, 0, 1), brep.GetVertex(2));
    brep.GetTriangleVertices(0, out int a, out int b, out int c);
    Assert.Equal((0, 2, 1), (a, b, c));
  }

  [Theory]
  [InlineData("obj\n", "not a PLY file", 1)]
  [InlineData("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no end_header", 4)]
  [InlineData("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n", "ends inside", 8)]
  [InlineData("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 1 2\n", "outside 0..0", 11)]
  [InlineData("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 zero 0\n", "'zero' is not a number", 8)]
  [InlineData("ply\nformat foo 1.0\nend_header\n", "unknown format", 3)]
  public void Broken_files_are_errors_naming_file_and_line(string text, string problem, int line)
  {
    string path = Write("bad.ply", text);
    var ex = Assert.Throws<MeshFormatException>(() => new StanfordPly().ReadBrep(path, new SceneBrep()));
    Assert.Contains(problem, ex.Message);
    Assert.Equal(line, ex.LineNumber);
    Assert.Equal(path, ex.FileName);
  }
}
