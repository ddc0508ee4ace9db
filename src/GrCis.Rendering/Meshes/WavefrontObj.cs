using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using OpenTK.Mathematics;
using Rendering;

namespace Scene3D;

/// <summary>
/// Reader (and a simple writer) of the text Wavefront OBJ format into a <see cref="SceneBrep"/>.
/// Supports <c>v</c>, <c>vt</c>, <c>vn</c> and <c>f</c> with the forms <c>v</c>, <c>v/vt</c>,
/// <c>v//vn</c>, <c>v/vt/vn</c>, negative (relative) indices, polygons (fan-triangulated), <c>#</c>
/// comments and gzip-compressed files (<c>.gz</c>). Other statements (g, o, s, usemtl, mtllib, …)
/// are ignored, and so are unknown ones in a file that has OBJ statements; binary data, or a text
/// without any OBJ statement, is not an OBJ file. An OBJ without faces gives an empty mesh.
/// Attributes are per vertex in <see cref="SceneBrep"/>: a position used with different texture
/// coordinates or normals is duplicated. Malformed lines and files that are not OBJ throw
/// <see cref="MeshFormatException"/> naming the file and line.
/// </summary>
public class WavefrontObj
{
  /// <summary>Negate z of positions and normals (left-handed data).</summary>
  public bool MirrorConversion { get; set; }

  /// <summary>Replace the texture coordinate v by 1 − v.</summary>
  public bool TextureUpsideDown { get; set; }

  /// <summary>Reads a file (gzip when the name ends with <c>.gz</c>) into a reset scene; returns the number of triangles.</summary>
  public int ReadBrep(string fileName, SceneBrep scene)
  {
    ArgumentException.ThrowIfNullOrEmpty(fileName);
    ArgumentNullException.ThrowIfNull(scene);
    fileName = Utilities.DataFiles.Resolve(fileName);
    Stream file = File.OpenRead(fileName);
    Stream data;
    try
    {
      data = fileName.EndsWith(".gz", StringComparison.OrdinalIgnoreCase) ? new CheckedGzipStream(file) : file;
    }
    catch (InvalidDataException e)
    {
      file.Dispose();
      throw new MeshFormatException(fileName, 1, e.Message, e);
    }
    using var reader = new StreamReader(data);
    scene.Reset();
    return Read(reader, scene, Matrix4d.Identity, fileName);
  }

  /// <summary>Reads from an open reader into a reset scene; returns the number of triangles.</summary>
  public int ReadBrep(TextReader reader, SceneBrep scene)
  {
    ArgumentNullException.ThrowIfNull(reader);
    ArgumentNullException.ThrowIfNull(scene);
    scene.Reset();
    return Read(reader, scene, Matrix4d.Identity, "(stream)");
  }

  /// <summary>Appends the mesh transformed by <paramref name="m"/> (instancing) to the scene; returns the number of triangles.</summary>
  public int ReadBrep(TextReader reader, SceneBrep scene, Matrix4d m, string sourceName = "(stream)")
  {
    ArgumentNullException.ThrowIfNull(reader);
    ArgumentNullException.ThrowIfNull(scene);
    return Read(reader, scene, m, sourceName);
  }

  /// <summary>The next line; damaged compressed data is reported at the line where it was found.</summary>
  static string? NextLine(TextReader reader, string name, int linesRead)
  {
    try
    {
      return reader.ReadLine();
    }
    catch (InvalidDataException e)
    {
      throw new MeshFormatException(name, linesRead + 1, "corrupt compressed data: " + e.Message, e);
    }
  }

  int Read(TextReader reader, SceneBrep scene, Matrix4d m, string name)
  {
    var positions = new List<int>(1024);        // OBJ position index → scene vertex
    var txtCoords = new List<Vector2>();
    var normals = new List<Vector3>();
    var bound = new List<(int vt, int vn)>();   // attributes already given to each position's vertex
    var duplicates = new Dictionary<(int v, int vt, int vn), int>();
    var face = new List<int>(8);
    Matrix4d normalMatrix = m.Inverted();
    int triangles = 0;
    int lineNo = 0;
    bool anyStatement = false;     // an OBJ statement seen (read or ignored)
    int foreignLine = 0;           // first line whose keyword is no OBJ statement
    string foreignKeyword = "";

    string? line;
    while ((line = NextLine(reader, name, lineNo)) != null)
    {
      lineNo++;
      int binary = BinaryCharacter(line);
      if (binary >= 0)
        throw new MeshFormatException(name, lineNo, $"binary data (character 0x{(int)line[binary]:X2}): not a Wavefront OBJ text file");
      int hash = line.IndexOf('#');
      ReadOnlySpan<char> text = (hash >= 0 ? line.AsSpan(0, hash) : line.AsSpan()).Trim();
      if (text.IsEmpty)
        continue;

      var tokens = new Tokens(text);
      ReadOnlySpan<char> keyword = tokens.Next();
      switch (keyword)
      {
        case "v":
        {
          Vector3d p = new(Number(ref tokens, name, lineNo, "v"), Number(ref tokens, name, lineNo, "v"), Number(ref tokens, name, lineNo, "v"));
          if (MirrorConversion)
            p.Z = -p.Z;
          positions.Add(scene.AddVertex((Vector3)Vector3d.TransformPosition(p, m)));
          bound.Add((-2, -2));
          break;
        }
        case "vt":
        {
          double u = Number(ref tokens, name, lineNo, "vt");
          double v = tokens.HasMore ? Number(ref tokens, name, lineNo, "vt") : 0.0;
          if (TextureUpsideDown)
            v = 1.0 - v;
          txtCoords.Add(new Vector2((float)u, (float)v));
          break;
        }
        case "vn":
        {
          Vector3d n = new(Number(ref tokens, name, lineNo, "vn"), Number(ref tokens, name, lineNo, "vn"), Number(ref tokens, name, lineNo, "vn"));
          if (MirrorConversion)
            n.Z = -n.Z;
          normals.Add((Vector3)Vector3d.TransformNormalInverse(n, normalMatrix));
          break;
        }
        case "f":
        {
          face.Clear();
          while (tokens.HasMore)
          {
            ReadOnlySpan<char> corner = tokens.Next();
            ParseCorner(corner, positions.Count, txtCoords.Count, normals.Count, name, lineNo, out int vi, out int ti, out int ni);
            face.Add(Bind(scene, positions, bound, duplicates, txtCoords, normals, vi, ti, ni));
          }
          if (face.Count < 3)
            throw new MeshFormatException(name, lineNo, $"a face needs at least 3 vertices, found {face.Count}");
          for (int i = 1; i + 1 < face.Count; i++)
          {
            scene.AddTriangle(face[0], face[i], face[i + 1]);
            triangles++;
          }
          break;
        }
        default:
          // g, o, s, usemtl, mtllib, l, p, … are not needed.
          if (IsOtherStatement(keyword))
            anyStatement = true;
          else if (foreignLine == 0)
          {
            foreignLine = lineNo;
            foreignKeyword = keyword.Length > 20 ? keyword[..20].ToString() + "…" : keyword.ToString();
          }
          continue;
      }
      anyStatement = true;
    }
    // Unknown statements among OBJ ones are skipped; a text with none at all is some other file.
    if (!anyStatement && foreignLine > 0)
      throw new MeshFormatException(name, foreignLine, $"'{foreignKeyword}' is not an OBJ statement and the file has none: not a Wavefront OBJ file");
    return triangles;
  }

  /// <summary>Index of the first control character that no text file holds (not whitespace, not DOS's end-of-file mark), or −1.</summary>
  static int BinaryCharacter(string line)
  {
    for (int i = 0; i < line.Length; i++)
    {
      char c = line[i];
      if ((c < ' ' && c != '\t' && c != '\v' && c != '\f' && c != '\r' && c != '\x1A') || c == '\x7F')
        return i;
    }
    return -1;
  }

  /// <summary>The OBJ statements this reader skips (grouping, materials, free-form geometry, display attributes).</summary>
  static bool IsOtherStatement(ReadOnlySpan<char> keyword) => keyword switch
  {
    "vp" or "l" or "p" or "g" or "o" or "s" or "mg" or "usemtl" or "mtllib" or "usemap" or "maplib" or "cstype" or "deg"
      or "bmat" or "step" or "curv" or "curv2" or "surf" or "parm" or "trim" or "hole" or "scrv" or "sp" or "end" or "con"
      or "bevel" or "c_interp" or "d_interp" or "lod" or "shadow_obj" or "trace_obj" or "ctech" or "stech" or "call"
      or "csh" => true,
    _ => false,
  };

  /// <summary>The scene vertex for a corner: the position's own vertex, or a copy when its attributes differ.</summary>
  static int Bind(SceneBrep scene, List<int> positions, List<(int vt, int vn)> bound,
                  Dictionary<(int, int, int), int> duplicates, List<Vector2> txtCoords, List<Vector3> normals,
                  int vi, int ti, int ni)
  {
    int vertex = positions[vi];
    (int bt, int bn) = bound[vi];
    if (bt == -2)
    {
      bound[vi] = (ti, ni);
      Assign(scene, vertex, txtCoords, normals, ti, ni);
      return vertex;
    }
    if ((ti < 0 || bt < 0 || ti == bt) && (ni < 0 || bn < 0 || ni == bn))
    {
      // Compatible: fill in attributes the vertex did not have yet.
      bound[vi] = (bt >= 0 ? bt : ti, bn >= 0 ? bn : ni);
      Assign(scene, vertex, txtCoords, normals, bt >= 0 ? -1 : ti, bn >= 0 ? -1 : ni);
      return vertex;
    }
    if (duplicates.TryGetValue((vi, ti, ni), out int copy))
      return copy;
    copy = scene.AddVertex(scene.GetVertex(vertex));
    duplicates.Add((vi, ti, ni), copy);
    Assign(scene, copy, txtCoords, normals, ti, ni);
    return copy;
  }

  static void Assign(SceneBrep scene, int vertex, List<Vector2> txtCoords, List<Vector3> normals, int ti, int ni)
  {
    if (ti >= 0)
      scene.SetTxtCoord(vertex, txtCoords[ti]);
    if (ni >= 0)
      scene.SetNormal(vertex, normals[ni]);
  }

  /// <summary>Parses <c>v</c>, <c>v/vt</c>, <c>v//vn</c> or <c>v/vt/vn</c> into 0-based indices (−1 when absent).</summary>
  static void ParseCorner(ReadOnlySpan<char> corner, int nv, int nt, int nn, string name, int lineNo, out int vi, out int ti, out int ni)
  {
    ti = ni = -1;
    int s1 = corner.IndexOf('/');
    ReadOnlySpan<char> vPart = s1 < 0 ? corner : corner[..s1];
    vi = Index(vPart, nv, "vertex", corner, name, lineNo);
    if (s1 < 0)
      return;
    ReadOnlySpan<char> rest = corner[(s1 + 1)..];
    int s2 = rest.IndexOf('/');
    ReadOnlySpan<char> tPart = s2 < 0 ? rest : rest[..s2];
    if (!tPart.IsEmpty)
      ti = Index(tPart, nt, "texture coordinate", corner, name, lineNo);
    if (s2 >= 0)
    {
      ReadOnlySpan<char> nPart = rest[(s2 + 1)..];
      if (nPart.IsEmpty || nPart.IndexOf('/') >= 0)
        throw new MeshFormatException(name, lineNo, $"malformed face corner '{Echo(corner)}'");
      ni = Index(nPart, nn, "normal", corner, name, lineNo);
    }
  }

  /// <summary>1-based or negative (relative to the end) OBJ index → 0-based index, validated.</summary>
  static int Index(ReadOnlySpan<char> text, int count, string what, ReadOnlySpan<char> corner, string name, int lineNo)
  {
    if (!int.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int index))
      throw new MeshFormatException(name, lineNo, $"malformed {what} index '{Echo(text)}' in face corner '{Echo(corner)}'");
    int i = index > 0 ? index - 1 : count + index;
    if (index == 0 || i < 0 || i >= count)
      throw new MeshFormatException(name, lineNo, $"{what} index {index} out of range (1..{count} or -1..-{count} so far)");
    return i;
  }

  static double Number(ref Tokens tokens, string name, int lineNo, string keyword)
  {
    if (!tokens.HasMore)
      throw new MeshFormatException(name, lineNo, $"'{keyword}' needs more numbers");
    ReadOnlySpan<char> t = tokens.Next();
    if (!double.TryParse(t, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !double.IsFinite(value))
      throw new MeshFormatException(name, lineNo, $"'{Echo(t)}' is not a number (in '{keyword}')");
    return value;
  }

  /// <summary>Longest piece of the file a message quotes whole.</summary>
  internal const int MaxEcho = 40;

  /// <summary>A token as a message quotes it: a 50 MB "number" must not become a 50 MB error line.</summary>
  static string Echo(ReadOnlySpan<char> token) => token.Length <= MaxEcho ? token.ToString() : string.Concat(token[..MaxEcho], "…");

  /// <summary>Whitespace-separated tokens of a line, without allocation.</summary>
  ref struct Tokens
  {
    ReadOnlySpan<char> rest;

    public Tokens(ReadOnlySpan<char> line) => rest = line.TrimStart();

    public readonly bool HasMore => !rest.IsEmpty;

    public ReadOnlySpan<char> Next()
    {
      int end = 0;
      while (end < rest.Length && !char.IsWhiteSpace(rest[end]))
        end++;
      ReadOnlySpan<char> token = rest[..end];
      rest = rest[end..].TrimStart();
      return token;
    }
  }

  /// <summary>Writes positions, normals (when present) and triangles.</summary>
  public void WriteBrep(TextWriter writer, SceneBrep scene)
  {
    ArgumentNullException.ThrowIfNull(writer);
    ArgumentNullException.ThrowIfNull(scene);
    CultureInfo ci = CultureInfo.InvariantCulture;
    for (int i = 0; i < scene.Vertices; i++)
    {
      Vector3 v = scene.GetVertex(i);
      writer.WriteLine(string.Format(ci, "v {0} {1} {2}", v.X, v.Y, v.Z));
    }
    bool hasNormals = scene.Normals > 0;
    if (hasNormals)
      for (int i = 0; i < scene.Vertices; i++)
      {
        Vector3 n = scene.GetNormal(i);
        writer.WriteLine(string.Format(ci, "vn {0} {1} {2}", n.X, n.Y, n.Z));
      }
    for (int i = 0; i < scene.Triangles; i++)
    {
      scene.GetTriangleVertices(i, out int a, out int b, out int c);
      a++;
      b++;
      c++;
      writer.WriteLine(hasNormals
        ? string.Format(ci, "f {0}//{0} {1}//{1} {2}//{2}", a, b, c)
        : string.Format(ci, "f {0} {1} {2}", a, b, c));
    }
  }
}
