using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace Scene3D;

/// <summary>
/// A triangle mesh (boundary representation) with optional per-vertex normals, colours and
/// texture coordinates, and a corner table (Rossignac): corner c belongs to triangle c / 3,
/// <see cref="cVertex"/> gives its vertex and, after <see cref="BuildCornerTable"/>,
/// <see cref="cOpposite"/> the corner across the opposite edge. Coordinates are single
/// precision, as in GrCis. A mesh may instead hold lines (<see cref="AddLine"/>), never both.
/// </summary>
public partial class SceneBrep : ICloneable
{
  /// <summary>Invalid handle (vertex, triangle, corner).</summary>
  public const int NULL = -1;

  // GrCis's names; protected as in GrCis, for subclasses.
  protected List<Vector3> geometry = new();
  protected List<Vector3>? normals;
  protected List<Vector3>? colors;
  protected List<Vector2>? txtCoords;
  protected List<int> vertexPtr = new();
  protected List<int>? oppositePtr;

  /// <summary>Statistics of the last <see cref="BuildCornerTable"/>: unmatched and shared edges.</summary>
  public int statEdges;
  public int statShared;

  public SceneBrep() => Reset();

  /// <summary>Removes everything.</summary>
  public void Reset()
  {
    geometry = new List<Vector3>(256);
    normals = colors = null;
    txtCoords = null;
    vertexPtr = new List<int>(256);
    oppositePtr = null;
    lines = false;
    LineWidth = 2.0f;
  }

  object ICloneable.Clone() => Clone();

  public SceneBrep Clone()
  {
    var copy = new SceneBrep
    {
      geometry = new List<Vector3>(geometry),
      normals = normals == null ? null : new List<Vector3>(normals),
      colors = colors == null ? null : new List<Vector3>(colors),
      txtCoords = txtCoords == null ? null : new List<Vector2>(txtCoords),
      vertexPtr = new List<int>(vertexPtr),
      oppositePtr = oppositePtr == null ? null : new List<int>(oppositePtr),
      statEdges = statEdges,
      statShared = statShared,
      lines = lines,
      LineWidth = LineWidth,
    };
    return copy;
  }

  /// <summary>Makes room for more vertices (and three corners per vertex).</summary>
  public void Reserve(int additionalVertices)
  {
    if (additionalVertices <= 0)
      return;
    int v = geometry.Count + additionalVertices;
    geometry.Capacity = Math.Max(geometry.Capacity, v);
    if (normals != null) normals.Capacity = Math.Max(normals.Capacity, v);
    if (colors != null) colors.Capacity = Math.Max(colors.Capacity, v);
    if (txtCoords != null) txtCoords.Capacity = Math.Max(txtCoords.Capacity, v);
    vertexPtr.Capacity = Math.Max(vertexPtr.Capacity, vertexPtr.Count + 3 * additionalVertices);
  }

  public int Vertices => geometry.Count;

  /// <summary>Number of normals: 0 or <see cref="Vertices"/>.</summary>
  public int Normals => normals?.Count ?? 0;

  public bool HasNormals() => normals != null;

  public int Colors => colors?.Count ?? 0;

  public bool HasColors() => colors != null;

  public int TxtCoords => txtCoords?.Count ?? 0;

  public bool HasTxtCoords() => txtCoords != null;

  /// <summary>Number of triangles; 0 when the mesh holds lines.</summary>
  public int Triangles => lines ? 0 : vertexPtr.Count / 3;

  /// <summary>Number of corners (three per triangle); 0 when the mesh holds lines.</summary>
  public int Corners => lines ? 0 : vertexPtr.Count;

  /// <summary>Adds a vertex and returns its handle (attributes present so far get defaults).</summary>
  public int AddVertex(Vector3 v)
  {
    int handle = geometry.Count;
    geometry.Add(v);
    normals?.Add(Vector3.UnitY);
    colors?.Add(Vector3.One);
    txtCoords?.Add(default);
    return handle;
  }

  public Vector3 GetVertex(int v) => geometry[CheckVertex(v)];

  public void SetVertex(int v, Vector3 pos) => geometry[CheckVertex(v)] = pos;

  public void SetNormal(int v, Vector3 normal)
  {
    CheckVertex(v);
    normals ??= Filled(Vector3.UnitY);
    normals[v] = normal;
  }

  public Vector3 GetNormal(int v) => (normals ?? throw NoAttribute("normals"))[CheckVertex(v)];

  public void SetColor(int v, Vector3 color)
  {
    CheckVertex(v);
    colors ??= Filled(Vector3.One);
    colors[v] = color;
  }

  public Vector3 GetColor(int v) => (colors ?? throw NoAttribute("colors"))[CheckVertex(v)];

  public void SetTxtCoord(int v, Vector2 txt)
  {
    CheckVertex(v);
    if (txtCoords == null)
    {
      txtCoords = new List<Vector2>(geometry.Capacity);
      for (int i = 0; i < geometry.Count; i++)
        txtCoords.Add(default);
    }
    txtCoords[v] = txt;
  }

  public Vector2 GetTxtCoord(int v) => (txtCoords ?? throw NoAttribute("texture coordinates"))[CheckVertex(v)];

  /// <summary>Adds a triangle (counter-clockwise seen from its front) and returns its handle; <see cref="NULL"/> when the mesh holds lines.</summary>
  public int AddTriangle(int v1, int v2, int v3)
  {
    if (!HasTriangles)
      return NULL;
    CheckVertex(v1);
    CheckVertex(v2);
    CheckVertex(v3);
    int corner = vertexPtr.Count;
    vertexPtr.Add(v1);
    vertexPtr.Add(v2);
    vertexPtr.Add(v3);
    if (oppositePtr != null)
    {
      oppositePtr.Add(NULL);
      oppositePtr.Add(NULL);
      oppositePtr.Add(NULL);
    }
    return corner / 3;
  }

  public void GetTriangleVertices(int tr, out int v1, out int v2, out int v3)
  {
    int c = CheckTriangle(tr) * 3;
    v1 = vertexPtr[c];
    v2 = vertexPtr[c + 1];
    v3 = vertexPtr[c + 2];
  }

  public void GetTriangleVertices(int tr, out Vector3 v1, out Vector3 v2, out Vector3 v3)
  {
    GetTriangleVertices(tr, out int a, out int b, out int c);
    v1 = geometry[a];
    v2 = geometry[b];
    v3 = geometry[c];
  }

  public void SetTriangleVertices(int tr, int v1, int v2, int v3)
  {
    int c = CheckTriangle(tr) * 3;
    vertexPtr[c] = CheckVertex(v1);
    vertexPtr[c + 1] = CheckVertex(v2);
    vertexPtr[c + 2] = CheckVertex(v3);
  }

  /// <summary>Grows the box [min, max] by the triangle's vertices.</summary>
  public void TriangleBoundingBox(int tr, ref Vector3 min, ref Vector3 max)
  {
    GetTriangleVertices(tr, out Vector3 a, out Vector3 b, out Vector3 c);
    foreach (Vector3 p in stackalloc[] { a, b, c })
    {
      min = new Vector3(MathF.Min(min.X, p.X), MathF.Min(min.Y, p.Y), MathF.Min(min.Z, p.Z));
      max = new Vector3(MathF.Max(max.X, p.X), MathF.Max(max.Y, p.Y), MathF.Max(max.Z, p.Z));
    }
  }

  /// <summary>Centroid of the vertices and the diagonal of their bounding box (4 for fewer than two vertices).</summary>
  public float GetDiameter(out Vector3 center)
  {
    if (geometry.Count < 2)
    {
      center = geometry.Count == 1 ? geometry[0] : Vector3.Zero;
      return 4.0f;
    }
    double cx = 0, cy = 0, cz = 0;
    Vector3 min = new Vector3(float.MaxValue), max = new Vector3(float.MinValue);
    foreach (Vector3 p in geometry)
    {
      cx += p.X;
      cy += p.Y;
      cz += p.Z;
      min = new Vector3(MathF.Min(min.X, p.X), MathF.Min(min.Y, p.Y), MathF.Min(min.Z, p.Z));
      max = new Vector3(MathF.Max(max.X, p.X), MathF.Max(max.Y, p.Y), MathF.Max(max.Z, p.Z));
    }
    int n = geometry.Count;
    center = new Vector3((float)(cx / n), (float)(cy / n), (float)(cz / n));
    return (max - min).Length;
  }

  /// <summary>Vertex normals as the average of the unit normals of the incident triangles.</summary>
  public void ComputeNormals()
  {
    if (!HasTriangles)
      return;
    var sum = new Vector3d[geometry.Count];
    for (int c = 0; c + 2 < vertexPtr.Count; c += 3)
    {
      int a = vertexPtr[c], b = vertexPtr[c + 1], d = vertexPtr[c + 2];
      Vector3d pa = geometry[a], pb = geometry[b], pd = geometry[d];
      Vector3d n = Vector3d.Cross(pb - pa, pd - pa);
      double len = n.Length;
      if (len == 0.0)
        continue;
      n /= len;
      sum[a] += n;
      sum[b] += n;
      sum[d] += n;
    }
    normals = new List<Vector3>(geometry.Count);
    foreach (Vector3d s in sum)
    {
      double len = s.Length;
      normals.Add(len > 0.0 ? (Vector3)(s / len) : Vector3.UnitY);
    }
  }

  /// <summary>Links opposite corners across shared edges (two triangles per edge at most are linked).</summary>
  public void BuildCornerTable()
  {
    if (!HasTriangles)
    {
      oppositePtr = null;
      return;
    }
    int n = vertexPtr.Count;
    oppositePtr = new List<int>(n);
    for (int i = 0; i < n; i++)
      oppositePtr.Add(NULL);
    var open = new Dictionary<(int, int), int>();
    statEdges = statShared = 0;
    for (int c = 0; c < n; c++)
    {
      int a = vertexPtr[cNext(c)], b = vertexPtr[cPrev(c)];
      var edge = a < b ? (a, b) : (b, a);
      if (open.Remove(edge, out int other))
      {
        oppositePtr[other] = c;
        oppositePtr[c] = other;
        statShared++;
      }
      else
      {
        open.Add(edge, c);
        statEdges++;
      }
    }
  }

  public static int cTriangle(int c) => c / 3;

  public static int tCorner(int tr) => tr * 3;

  public static int cNext(int c) => c % 3 == 2 ? c - 2 : c + 1;

  public static int cPrev(int c) => c % 3 == 0 ? c + 2 : c - 1;

  public int cVertex(int c) => c < 0 ? NULL : vertexPtr[c];

  public int cOpposite(int c) => c < 0 || oppositePtr == null ? NULL : oppositePtr[c];

  public int cRight(int c) => cOpposite(cNext(c));

  public int cLeft(int c) => cOpposite(cPrev(c));

  List<Vector3> Filled(Vector3 value)
  {
    var list = new List<Vector3>(geometry.Capacity);
    for (int i = 0; i < geometry.Count; i++)
      list.Add(value);
    return list;
  }

  int CheckVertex(int v)
  {
    if ((uint)v >= (uint)geometry.Count)
      throw new ArgumentOutOfRangeException(nameof(v), v, $"Vertex handle must be in [0, {geometry.Count}).");
    return v;
  }

  int CheckTriangle(int tr)
  {
    if ((uint)tr >= (uint)Triangles)
      throw new ArgumentOutOfRangeException(nameof(tr), tr, $"Triangle handle must be in [0, {Triangles}).");
    return tr;
  }

  static InvalidOperationException NoAttribute(string what) => new($"The mesh has no {what}.");
}
