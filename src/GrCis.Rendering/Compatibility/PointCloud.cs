using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// GrCis's point cloud: points with colour and normal collected per thread (index = <see cref="MT.threadID"/>,
/// so threads never share a list), saved as an ASCII PLY file.
/// </summary>
public class PointCloud
{
  /// <summary>Per thread: x, y, z, r, g, b, nx, ny, nz for each point.</summary>
  public List<float>[] cloud;

  public int numberOfElements;

  public PointCloud(int numberOfThreads)
  {
    cloud = new List<float>[Math.Max(1, numberOfThreads)];
    for (int i = 0; i < cloud.Length; i++)
      cloud[i] = new List<float>();
  }

  public bool IsCloudEmpty => numberOfElements == 0;

  /// <summary>Adds a point to list <paramref name="index"/> (the calling thread's).</summary>
  public void AddToPointCloud(Vector3d coord, double[] color, Vector3d normal, int index)
  {
    List<float> list = cloud[index];
    list.Add((float)coord.X);
    list.Add((float)coord.Y);
    list.Add((float)coord.Z);
    for (int b = 0; b < 3; b++)
      list.Add((float)(color.Length > 0 ? color[Math.Min(b, color.Length - 1)] : 0.0));
    list.Add((float)normal.X);
    list.Add((float)normal.Y);
    list.Add((float)normal.Z);
    System.Threading.Interlocked.Increment(ref numberOfElements);
  }

  /// <summary>Writes every point as ASCII PLY: position, 8-bit colour, normal.</summary>
  public void SaveToPLYFile(string fileName)
  {
    using var w = new StreamWriter(fileName);
    w.WriteLine("ply");
    w.WriteLine("format ascii 1.0");
    w.WriteLine(string.Create(CultureInfo.InvariantCulture, $"element vertex {numberOfElements}"));
    foreach (string p in new[] { "float x", "float y", "float z", "uchar red", "uchar green", "uchar blue", "float nx", "float ny", "float nz" })
      w.WriteLine("property " + p);
    w.WriteLine("end_header");
    foreach (List<float> list in cloud)
      for (int i = 0; i + 8 < list.Count; i += 9)
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
          $"{list[i]} {list[i + 1]} {list[i + 2]} {ToByte(list[i + 3])} {ToByte(list[i + 4])} {ToByte(list[i + 5])} {list[i + 6]} {list[i + 7]} {list[i + 8]}"));
  }

  static int ToByte(float c) => (int)Math.Clamp(Math.Round(c * 255.0), 0.0, 255.0);
}
