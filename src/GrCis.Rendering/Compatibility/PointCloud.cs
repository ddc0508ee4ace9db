using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// GrCis's point cloud: points with colour and normal collected per thread (index = <see cref="MT.threadID"/>,
/// so threads never share a list), saved as an ASCII PLY file in the PLY world's axes (z negated, see
/// <see cref="AxesCorrector"/>) and read back from such a file.
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

  /// <summary>Adds a point to list <paramref name="index"/> (the calling thread's; a negative index, a thread that is not a render worker, is ignored).</summary>
  public void AddToPointCloud(Vector3d coord, double[] color, Vector3d normal, int index)
  {
    if (index < 0)
      return;
    coord = AxesCorrector(coord);
    normal = AxesCorrector(normal);
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

  // GrCis truncates: (int)(c · 255), clamped.
  static int ToByte(float c) => Math.Clamp((int)(c * 255.0f), 0, 255);

  static readonly string[] header =
  {
    "ply", "format ascii 1.0", "element vertex", "property float x", "property float y", "property float z",
    "property uchar red", "property uchar green", "property uchar blue", "property float nx", "property float ny",
    "property float nz", "end_header",
  };

  /// <summary>
  /// Replaces the cloud by the points of a file <see cref="SaveToPLYFile"/> wrote (one list; colours back to 0–1),
  /// so saving it again writes the same points.
  /// </summary>
  /// <exception cref="InvalidDataException">The file is not such a file: <c>file(line): what is wrong</c>.</exception>
  public void ReadFromFile(string fileName)
  {
    fileName = Utilities.DataFiles.Resolve(fileName);
    using var reader = new StreamReader(fileName);
    int count;
    try
    {
      count = ReadPLYFileHeader(reader);
    }
    catch (InvalidDataException e)
    {
      throw new InvalidDataException($"{fileName}{e.Message}", e);
    }
    var points = new List<float>(checked(count * 9));
    for (int i = 0; i < count; i++)
    {
      int line = header.Length + i + 1;
      string[]? values = reader.ReadLine()?.Split(' ', StringSplitOptions.RemoveEmptyEntries);
      if (values == null)
        throw new InvalidDataException($"{fileName}({line}): the file ends after {i} of its {count} points");
      if (values.Length != 9)
        throw new InvalidDataException($"{fileName}({line}): a point has 9 numbers (x y z red green blue nx ny nz), this line has {values.Length}");
      for (int k = 0; k < 9; k++)
      {
        if (!float.TryParse(values[k], NumberStyles.Float, CultureInfo.InvariantCulture, out float v))
          throw new InvalidDataException($"{fileName}({line}): '{values[k]}' is not a number");
        points.Add(k is >= 3 and <= 5 ? v / 255.0f : v);
      }
    }
    cloud = new[] { points };
    numberOfElements = count;
  }

  /// <summary>
  /// Reads the header <see cref="SaveToPLYFile"/> writes (13 lines; the third is <c>element vertex N</c>) and returns N.
  /// </summary>
  /// <exception cref="InvalidDataException">A line differs: <c>(line): what was expected</c>.</exception>
  public int ReadPLYFileHeader(StreamReader streamReader)
  {
    ArgumentNullException.ThrowIfNull(streamReader);
    int count = -1;
    for (int i = 0; i < header.Length; i++)
    {
      string? line = streamReader.ReadLine()?.Trim();
      if (line == null)
        throw new InvalidDataException($"({i + 1}): the file ends in its header");
      if (header[i] == "element vertex")
      {
        string[] parts = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
        if (parts.Length != 3 || parts[0] != "element" || parts[1] != "vertex" ||
            !int.TryParse(parts[2], NumberStyles.None, CultureInfo.InvariantCulture, out count))
          throw new InvalidDataException($"({i + 1}): expected 'element vertex <count>', found '{line}'");
      }
      else if (line != header[i])
        throw new InvalidDataException($"({i + 1}): expected '{header[i]}', found '{line}'");
    }
    return count;
  }

  /// <summary>A ray tracer's position or direction in the PLY world's axes: z negated; zero for null.</summary>
  public static Vector3d AxesCorrector(Vector3d? position) =>
    position is Vector3d p ? new Vector3d(p.X, p.Y, -p.Z) : Vector3d.Zero;
}
