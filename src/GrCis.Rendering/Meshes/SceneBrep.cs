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
  /// <summary>Vertex positions, indexed by vertex handle.</summary>
  protected List<Vector3> geometry = new();
  /// <summary>Vertex normals (one per vertex), or null when the mesh has none.</summary>
  protected List<Vector3>? normals;
  /// <summary>Vertex colours, RGB in [0, 1] (one per vertex), or null when the mesh has none.</summary>
  protected List<Vector3>? colors;
  /// <summary>Vertex texture coordinates (one per vertex), or null when the mesh has none.</summary>
  protected List<Vector2>? txtCoords;
  /// <summary>The corner table's vertex of each corner: three corners per triangle (or two per line in line mode).</summary>
  protected List<int> vertexPtr = new();
  /// <summary>The corner table's opposite corner of each corner (<see cref="NULL"/> on a border), or null until <see cref="BuildCornerTable"/>.</summary>
  protected List<int>? oppositePtr;

  /// <summary>Statistics of the last <see cref="BuildCornerTable"/>: edges found (an edge of two triangles counts once; see <see cref="statShared"/>).</summary>
  public int statEdges;
  /// <summary>Statistics of the last <see cref="BuildCornerTable"/>: edges shared by two triangles (linked).</summary>
  public int statShared;

  /// <summary>An empty mesh.</summary>
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

  /// <summary>A deep copy: its own lists of vertices, attributes and corners.</summary>
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

  /// <summary>Number of vertices.</summary>
  public int Vertices => geometry.Count;

  /// <summary>Number of normals: 0 or <see cref="Vertices"/>.</summary>
  public int Normals => normals?.Count ?? 0;

  /// <summary>True when the mesh has vertex normals.</summary>
  public bool HasNormals() => normals != null;

  /// <summary>Number of vertex colours: 0 or <see cref="Vertices"/>.</summary>
  public int Colors => colors?.Count ?? 0;

  /// <summary>True when the mesh has vertex colours.</summary>
  public bool HasColors() => colors != null;

  /// <summary>Number of texture coordinates: 0 or <see cref="Vertices"/>.</summary>
  public int TxtCoords => txtCoords?.Count ?? 0;

  /// <summary>True when the mesh has texture coordinates.</summary>
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

  /// <summary>Position of vertex <paramref name="v"/>.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public Vector3 GetVertex(int v) => geometry[CheckVertex(v)];

  /// <summary>Moves vertex <paramref name="v"/> to <paramref name="pos"/>.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public void SetVertex(int v, Vector3 pos) => geometry[CheckVertex(v)] = pos;

  /// <summary>Sets the normal of vertex <paramref name="v"/>; the first call gives every other vertex the normal +y.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public void SetNormal(int v, Vector3 normal)
  {
    CheckVertex(v);
    normals ??= Filled(Vector3.UnitY);
    normals[v] = normal;
  }

  /// <summary>Normal of vertex <paramref name="v"/>.</summary>
  /// <exception cref="InvalidOperationException">The mesh has no normals.</exception>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public Vector3 GetNormal(int v) => (normals ?? throw NoAttribute("normals"))[CheckVertex(v)];

  /// <summary>Sets the colour (RGB) of vertex <paramref name="v"/>; the first call gives every other vertex white.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public void SetColor(int v, Vector3 color)
  {
    CheckVertex(v);
    colors ??= Filled(Vector3.One);
    colors[v] = color;
  }

  /// <summary>Colour of vertex <paramref name="v"/>.</summary>
  /// <exception cref="InvalidOperationException">The mesh has no colours.</exception>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
  public Vector3 GetColor(int v) => (colors ?? throw NoAttribute("colors"))[CheckVertex(v)];

  /// <summary>Sets the texture coordinates of vertex <paramref name="v"/>; the first call gives every other vertex (0, 0).</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
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

  /// <summary>Texture coordinates of vertex <paramref name="v"/>.</summary>
  /// <exception cref="InvalidOperationException">The mesh has no texture coordinates.</exception>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="v"/> is not a vertex handle.</exception>
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

  /// <summary>The three vertex handles of triangle <paramref name="tr"/>, in order.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="tr"/> is not a triangle handle.</exception>
  public void GetTriangleVertices(int tr, out int v1, out int v2, out int v3)
  {
    int c = CheckTriangle(tr) * 3;
    v1 = vertexPtr[c];
    v2 = vertexPtr[c + 1];
    v3 = vertexPtr[c + 2];
  }

  /// <summary>The three vertex positions of triangle <paramref name="tr"/>, in order.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="tr"/> is not a triangle handle.</exception>
  public void GetTriangleVertices(int tr, out Vector3 v1, out Vector3 v2, out Vector3 v3)
  {
    GetTriangleVertices(tr, out int a, out int b, out int c);
    v1 = geometry[a];
    v2 = geometry[b];
    v3 = geometry[c];
  }

  /// <summary>Gives triangle <paramref name="tr"/> three other vertices (the corner table is not updated: build it again).</summary>
  /// <exception cref="ArgumentOutOfRangeException">A handle is out of range.</exception>
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

  /// <summary>The triangle corner <paramref name="c"/> belongs to.</summary>
  public static int cTriangle(int c) => c / 3;

  /// <summary>The first corner of triangle <paramref name="tr"/> (the others follow it).</summary>
  public static int tCorner(int tr) => tr * 3;

  /// <summary>The next corner of the same triangle (in the order of its vertices, cyclically).</summary>
  public static int cNext(int c) => c % 3 == 2 ? c - 2 : c + 1;

  /// <summary>The previous corner of the same triangle (cyclically).</summary>
  public static int cPrev(int c) => c % 3 == 0 ? c + 2 : c - 1;

  /// <summary>The vertex of corner <paramref name="c"/>; <see cref="NULL"/> for a negative corner.</summary>
  public int cVertex(int c) => c < 0 ? NULL : vertexPtr[c];

  /// <summary>
  /// The corner of the neighbouring triangle across the edge opposite <paramref name="c"/>; <see cref="NULL"/> on a border,
  /// for a negative corner, or before <see cref="BuildCornerTable"/>.
  /// </summary>
  public int cOpposite(int c) => c < 0 || oppositePtr == null ? NULL : oppositePtr[c];

  /// <summary>The opposite of the next corner, <c>cOpposite(cNext(c))</c>: the corner across the edge from <paramref name="c"/> to its previous corner.</summary>
  public int cRight(int c) => cOpposite(cNext(c));

  /// <summary>The opposite of the previous corner, <c>cOpposite(cPrev(c))</c>: the corner across the edge from <paramref name="c"/> to its next corner.</summary>
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
