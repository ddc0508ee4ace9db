using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using OpenTK.Mathematics;
using Rendering;

namespace Scene3D;

/// <summary>
/// Stanford PLY meshes (ASCII, binary little- and big-endian, optionally gzipped) to and from
/// <see cref="SceneBrep"/>: vertex positions, normals (nx ny nz), texture coordinates (s t, u v or
/// texture_u texture_v) and colours (red green blue, 8-bit or float); faces as index lists, polygons
/// split into fans. Other elements and properties are skipped. A broken file is a
/// <see cref="MeshFormatException"/> naming the file and the line (ASCII) or element (binary).
/// </summary>
public class StanfordPly
{
  /// <summary>Swap y and z and reverse the winding (a z-up file).</summary>
  public bool Orientation { get; set; }

  /// <summary><see cref="WriteBrep"/> writes ASCII (true) or binary little-endian (false).</summary>
  public bool TextFormat { get; set; } = true;

  /// <summary>ASCII output ends lines with the platform's newline (true) or CR only.</summary>
  public bool NativeNewLine { get; set; } = true;

  /// <summary><see cref="WriteBrep"/> writes vertex normals when the mesh has them (default true); reading always takes them.</summary>
  public bool DoNormals { get; set; } = true;

  /// <summary><see cref="WriteBrep"/> writes texture coordinates when the mesh has them (default true); reading always takes them.</summary>
  public bool DoTxtCoords { get; set; } = true;

  /// <summary><see cref="WriteBrep"/> writes vertex colours when the mesh has them (default true); reading always takes them.</summary>
  public bool DoColors { get; set; } = true;

  /// <summary>Reads a file (gzip when it ends with <c>.gz</c>) into a reset scene; returns the number of triangles.</summary>
  public int ReadBrep(string fileName, SceneBrep scene)
  {
    ArgumentException.ThrowIfNullOrEmpty(fileName);
    ArgumentNullException.ThrowIfNull(scene);
    fileName = Utilities.DataFiles.Resolve(fileName);
    using Stream file = File.OpenRead(fileName);
    using Stream data = fileName.EndsWith(".gz", StringComparison.OrdinalIgnoreCase) ? new CheckedGzipStream(file) : file;
    scene.Reset();
    return Read(new BufferedStream(data), scene, Matrix4d.Identity, fileName);
  }

  /// <summary>Reads from the reader's stream (from its start when it can seek) into a reset scene.</summary>
  public int ReadBrep(StreamReader reader, SceneBrep scene)
  {
    ArgumentNullException.ThrowIfNull(scene);
    scene.Reset();
    return ReadBrep(reader, scene, Matrix4d.Identity);
  }

  /// <summary>Adds the mesh, transformed by <paramref name="m"/>, to <paramref name="scene"/>; returns the number of triangles.</summary>
  public int ReadBrep(StreamReader reader, SceneBrep scene, Matrix4d m)
  {
    ArgumentNullException.ThrowIfNull(reader);
    ArgumentNullException.ThrowIfNull(scene);
    // Binary PLY must be read as bytes: start over on the underlying stream.
    Stream s = reader.BaseStream;
    if (s.CanSeek)
    {
      reader.DiscardBufferedData();
      s.Position = 0;
    }
    return Read(s, scene, m, "(stream)");
  }

  sealed record Property(string Name, string Type, string? CountType);

  sealed record Element(string Name, int Count, List<Property> Properties);

  int Read(Stream s, SceneBrep scene, Matrix4d m, string name)
  {
    int line = 0;
    string Fail(string problem) => throw new MeshFormatException(name, Math.Max(line, 1), problem);

    // Header: ASCII lines up to end_header.
    string? first = ReadLine(s);
    line++;
    if (first?.Trim() != "ply")
      Fail("not a PLY file (the first line is not 'ply')");
    string format = "";
    var elements = new List<Element>();
    while (true)
    {
      string? text = ReadLine(s) ?? Fail("the header has no end_header");
      line++;
      string[] t = text.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
      if (t.Length == 0 || t[0] is "comment" or "obj_info")
        continue;
      if (t[0] == "end_header")
        break;
      switch (t[0])
      {
        case "format" when t.Length >= 2:
          format = t[1];
          break;
        case "element" when t.Length >= 3 && int.TryParse(t[2], NumberStyles.Integer, CultureInfo.InvariantCulture, out int count) && count >= 0:
          elements.Add(new Element(t[1], count, new List<Property>()));
          break;
        case "property" when elements.Count > 0 && t.Length >= 5 && t[1] == "list":
          elements[^1].Properties.Add(new Property(t[4], t[3], t[2]));
          break;
        case "property" when elements.Count > 0 && t.Length >= 3:
          elements[^1].Properties.Add(new Property(t[2], t[1], null));
          break;
        default:
          Fail($"unexpected header line '{text.Trim()}'");
          break;
      }
    }
    bool ascii = format == "ascii";
    bool bigEndian = format == "binary_big_endian";
    if (!ascii && !bigEndian && format != "binary_little_endian")
      Fail($"unknown format '{format}' (ascii, binary_little_endian or binary_big_endian)");

    var reader = new ValueReader(s, ascii, bigEndian);
    try
    {
      return ReadBody(reader, elements, scene, m, name, line);
    }
    catch (FormatException ex) when (ex is not MeshFormatException)
    {
      throw new MeshFormatException(name, line + Math.Max(reader.Line, 1), ex.Message, ex);
    }
  }

  int ReadBody(ValueReader reader, List<Element> elements, SceneBrep scene, Matrix4d m, string name, int headerLines)
  {
    // ASCII: the data line; binary: the line after the header, the element named in the message.
    string where = "";
    double Fail(string problem) => throw new MeshFormatException(name, headerLines + Math.Max(reader.Line, 1), where + problem);
    int v0 = scene.Vertices, faces = 0;
    Matrix4d normalMatrix = m.Inverted();
    var polygon = new List<int>();
    foreach (Element e in elements)
    {
      bool isVertex = e.Name == "vertex", isFace = e.Name == "face";
      for (int i = 0; i < e.Count; i++)
      {
        where = reader.Ascii ? "" : $"{e.Name} {i}: ";
        double x = 0, y = 0, z = 0, nx = 0, ny = 0, nz = 0, tu = 0, tv = 0, r = 0, g = 0, b = 0;
        bool hasNormal = false, hasTxt = false, hasColor = false;
        polygon.Clear();
        foreach (Property p in e.Properties)
        {
          if (p.CountType != null)
          {
            int n = (int)(reader.Next(p.CountType) ?? Fail("the file ends inside an element"));
            for (int k = 0; k < n; k++)
            {
              double index = reader.Next(p.Type) ?? Fail("the file ends inside a list");
              if (isFace && p.Name is "vertex_indices" or "vertex_index")
                polygon.Add((int)index);
            }
            continue;
          }
          double value = reader.Next(p.Type) ?? Fail("the file ends inside an element");
          if (!isVertex)
            continue;
          bool bytes = p.Type is "uchar" or "uint8" or "char" or "int8";
          switch (p.Name)
          {
            case "x": x = value; break;
            case "y": y = value; break;
            case "z": z = value; break;
            case "nx": nx = value; hasNormal = true; break;
            case "ny": ny = value; hasNormal = true; break;
            case "nz": nz = value; hasNormal = true; break;
            case "s" or "u" or "texture_u" or "texture_s": tu = value; hasTxt = true; break;
            case "t" or "v" or "texture_v" or "texture_t": tv = value; hasTxt = true; break;
            case "red": r = bytes ? value / 255.0 : value; hasColor = true; break;
            case "green": g = bytes ? value / 255.0 : value; hasColor = true; break;
            case "blue": b = bytes ? value / 255.0 : value; hasColor = true; break;
          }
        }
        reader.EndOfElement();

        if (isVertex)
        {
          if (!double.IsFinite(x) || !double.IsFinite(y) || !double.IsFinite(z))
            Fail("a vertex coordinate is not a finite number");
          var pos = Orientation ? new Vector3d(x, z, y) : new Vector3d(x, y, z);
          int v = scene.AddVertex((Vector3)Vector3d.TransformPosition(pos, m));
          if (hasNormal)
          {
            var n = Orientation ? new Vector3d(nx, nz, ny) : new Vector3d(nx, ny, nz);
            scene.SetNormal(v, (Vector3)Vector3d.TransformNormalInverse(n, normalMatrix));
          }
          if (hasTxt)
            scene.SetTxtCoord(v, new Vector2((float)tu, (float)tv));
          if (hasColor)
            scene.SetColor(v, new Vector3((float)r, (float)g, (float)b));
        }
        else if (isFace && polygon.Count >= 3)
        {
          int vertices = scene.Vertices - v0;
          foreach (int index in polygon)
            if (index < 0 || index >= vertices)
              Fail($"vertex index {index} is outside 0..{vertices - 1}");
          for (int k = 1; k + 1 < polygon.Count; k++)
          {
            if (Orientation)
              scene.AddTriangle(v0 + polygon[0], v0 + polygon[k + 1], v0 + polygon[k]);
            else
              scene.AddTriangle(v0 + polygon[0], v0 + polygon[k], v0 + polygon[k + 1]);
            faces++;
          }
        }
      }
    }
    return faces;
  }

  /// <summary>One header line of ASCII bytes (LF or CRLF), or null at the end.</summary>
  static string? ReadLine(Stream s)
  {
    var sb = new StringBuilder();
    int c;
    while ((c = s.ReadByte()) >= 0 && c != '\n')
      if (c != '\r')
        sb.Append((char)c);
    return c < 0 && sb.Length == 0 ? null : sb.ToString();
  }

  /// <summary>Scalar values of the body, as ASCII tokens (one element per line) or binary numbers.</summary>
  sealed class ValueReader
  {
    readonly Stream s;
    readonly bool bigEndian;
    readonly byte[] buffer = new byte[8];
    string[] tokens = Array.Empty<string>();
    int next;

    public ValueReader(Stream s, bool ascii, bool bigEndian)
    {
      this.s = s;
      Ascii = ascii;
      this.bigEndian = bigEndian;
    }

    public bool Ascii { get; }

    /// <summary>Body lines read so far (ASCII).</summary>
    public int Line { get; private set; }

    public double? Next(string type)
    {
      if (Ascii)
      {
        while (next >= tokens.Length)
        {
          string? text = ReadLine(s);
          if (text == null)
            return null;
          Line++;
          tokens = text.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
          next = 0;
        }
        return double.TryParse(tokens[next++], NumberStyles.Float, CultureInfo.InvariantCulture, out double v) ? v
          : throw new FormatException($"'{tokens[next - 1]}' is not a number");
      }
      int size = type switch
      {
        "char" or "int8" or "uchar" or "uint8" => 1,
        "short" or "int16" or "ushort" or "uint16" => 2,
        "int" or "int32" or "uint" or "uint32" or "float" or "float32" => 4,
        "double" or "float64" => 8,
        _ => throw new FormatException($"unknown property type '{type}'"),
      };
      if (s.ReadAtLeast(buffer.AsSpan(0, size), size, throwOnEndOfStream: false) < size)
        return null;
      Span<byte> b = buffer.AsSpan(0, size);
      if (bigEndian == BitConverter.IsLittleEndian)
        b.Reverse();
      return type switch
      {
        "char" or "int8" => (sbyte)b[0],
        "uchar" or "uint8" => b[0],
        "short" or "int16" => BitConverter.ToInt16(b),
        "ushort" or "uint16" => BitConverter.ToUInt16(b),
        "int" or "int32" => BitConverter.ToInt32(b),
        "uint" or "uint32" => BitConverter.ToUInt32(b),
        "float" or "float32" => BitConverter.ToSingle(b),
        _ => BitConverter.ToDouble(b),
      };
    }

    /// <summary>An ASCII element ends its line.</summary>
    public void EndOfElement()
    {
      if (Ascii)
        next = tokens.Length;
    }
  }

  /// <summary>
  /// Writes the scene: positions, and normals, texture coordinates (s t) and colours (float) where the
  /// scene has them and the Do* switches allow; ASCII or binary little-endian by <see cref="TextFormat"/>.
  /// </summary>
  public void WriteBrep(StreamWriter writer, SceneBrep scene)
  {
    ArgumentNullException.ThrowIfNull(writer);
    if (scene == null || scene.Triangles < 1)
      return;
    if (!NativeNewLine)
      writer.NewLine = "\r";
    bool normals = DoNormals && scene.HasNormals();
    bool txt = DoTxtCoords && scene.HasTxtCoords();
    bool colors = DoColors && scene.HasColors();
    char second = Orientation ? 'z' : 'y', third = Orientation ? 'y' : 'z';

    writer.WriteLine("ply");
    writer.WriteLine(TextFormat ? "format ascii 1.0" : "format binary_little_endian 1.0");
    writer.WriteLine($"element vertex {scene.Vertices}");
    writer.WriteLine("property float x");
    writer.WriteLine($"property float {second}");
    writer.WriteLine($"property float {third}");
    if (normals)
    {
      writer.WriteLine("property float nx");
      writer.WriteLine($"property float n{second}");
      writer.WriteLine($"property float n{third}");
    }
    if (txt)
    {
      writer.WriteLine("property float s");
      writer.WriteLine("property float t");
    }
    if (colors)
    {
      writer.WriteLine("property float red");
      writer.WriteLine("property float green");
      writer.WriteLine("property float blue");
    }
    writer.WriteLine($"element face {scene.Triangles}");
    writer.WriteLine("property list uchar int vertex_indices");
    writer.WriteLine("end_header");

    var values = new List<float>(12);
    BinaryWriter? bin = null;
    if (!TextFormat)
    {
      writer.Flush();
      bin = new BinaryWriter(writer.BaseStream, Encoding.ASCII, leaveOpen: true);
    }
    for (int i = 0; i < scene.Vertices; i++)
    {
      values.Clear();
      Vector3 p = scene.GetVertex(i);
      values.AddRange(new[] { p.X, p.Y, p.Z });
      if (normals)
      {
        Vector3 n = scene.GetNormal(i);
        values.AddRange(new[] { n.X, n.Y, n.Z });
      }
      if (txt)
      {
        Vector2 t = scene.GetTxtCoord(i);
        values.AddRange(new[] { t.X, t.Y });
      }
      if (colors)
      {
        Vector3 c = scene.GetColor(i);
        values.AddRange(new[] { c.X, c.Y, c.Z });
      }
      if (bin != null)
        foreach (float v in values)
          bin.Write(v);
      else
        writer.WriteLine(string.Join(' ', values.ConvertAll(v => v.ToString("R", CultureInfo.InvariantCulture))));
    }
    for (int i = 0; i < scene.Triangles; i++)
    {
      scene.GetTriangleVertices(i, out int a, out int b, out int c);
      (int second2, int third2) = Orientation ? (c, b) : (b, c);
      if (bin != null)
      {
        bin.Write((byte)3);
        bin.Write(a);
        bin.Write(second2);
        bin.Write(third2);
      }
      else
        writer.WriteLine($"3 {a} {second2} {third2}");
    }
    if (bin != null)
    {
      bin.Flush();
      bin.Dispose();
    }
    else
      writer.Flush();
  }
}
