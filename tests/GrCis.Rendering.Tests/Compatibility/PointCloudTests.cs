using System;
using System.IO;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>GrCis's point cloud: PLY in the PLY world's axes (z negated), GrCis's colour truncation, and reading back what it wrote.</summary>
public sealed class PointCloudTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-cloud-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  static PointCloud TwoThreads()
  {
    var cloud = new PointCloud(2);
    cloud.AddToPointCloud(new Vector3d(1.0, 2.0, 3.0), new[] { 1.0, 0.5, 0.0 }, new Vector3d(0.0, 0.0, 1.0), 0);
    cloud.AddToPointCloud(new Vector3d(-1.5, 0.25, -4.0), new[] { 0.999, 2.0, -1.0 }, new Vector3d(0.6, 0.8, 0.0), 1);
    cloud.AddToPointCloud(new Vector3d(9.0, 9.0, 9.0), new[] { 1.0, 1.0, 1.0 }, Vector3d.UnitX, -1);   // not a worker thread
    return cloud;
  }

  [Fact]
  public void Points_are_saved_with_z_negated_and_colours_truncated_to_bytes()
  {
    string ply = Path.Combine(dir, "cloud.ply");
    TwoThreads().SaveToPLYFile(ply);
    string[] lines = File.ReadAllLines(ply);
    Assert.Equal("element vertex 2", lines[2]);
    Assert.Equal("end_header", lines[12]);
    Assert.Equal("1 2 -3 255 127 0 0 0 -1", lines[13]);
    Assert.Equal("-1.5 0.25 4 254 255 0 0.6 0.8 -0", lines[14]);
    Assert.Equal(15, lines.Length);
  }

  [Fact]
  public void A_saved_cloud_reads_back_and_saves_the_same_file_again()
  {
    string first = Path.Combine(dir, "a.ply"), second = Path.Combine(dir, "b.ply");
    TwoThreads().SaveToPLYFile(first);
    var read = new PointCloud(1);
    read.ReadFromFile(first);
    Assert.Equal(2, read.numberOfElements);
    Assert.Equal(-3.0f, read.cloud[0][2]);
    read.SaveToPLYFile(second);
    Assert.Equal(File.ReadAllText(first), File.ReadAllText(second));
  }

  [Theory]
  [InlineData(0, "plx", "(1): expected 'ply'")]
  [InlineData(2, "element vertex many", "(3): expected 'element vertex <count>'")]
  [InlineData(6, "property uchar r", "(7): expected 'property uchar red'")]
  [InlineData(13, "1 2 3 4 5 6 7 8", "(14): a point has 9 numbers")]
  [InlineData(14, "1 2 3 4 5 6 7 8 x", "(15): 'x' is not a number")]
  public void A_damaged_file_is_refused_naming_file_and_line(int lineIndex, string replacement, string expected)
  {
    string ply = Path.Combine(dir, "bad.ply");
    TwoThreads().SaveToPLYFile(ply);
    string[] lines = File.ReadAllLines(ply);
    lines[lineIndex] = replacement;
    File.WriteAllLines(ply, lines);
    var e = Assert.Throws<InvalidDataException>(() => new PointCloud(1).ReadFromFile(ply));
    Assert.Equal(ply + expected, e.Message[..(ply.Length + expected.Length)]);
  }

  [Fact]
  public void A_file_cut_short_says_how_many_points_it_has()
  {
    string ply = Path.Combine(dir, "short.ply");
    TwoThreads().SaveToPLYFile(ply);
    string[] lines = File.ReadAllLines(ply);
    File.WriteAllLines(ply, lines[..14]);
    var e = Assert.Throws<InvalidDataException>(() => new PointCloud(1).ReadFromFile(ply));
    Assert.Equal($"{ply}(15): the file ends after 1 of its 2 points", e.Message);
  }

  [Fact]
  public void The_axes_corrector_negates_z_and_maps_null_to_zero()
  {
    Assert.Equal(new Vector3d(1, -2, -3), PointCloud.AxesCorrector(new Vector3d(1, -2, 3)));
    Assert.Equal(Vector3d.Zero, PointCloud.AxesCorrector(null));
  }
}
