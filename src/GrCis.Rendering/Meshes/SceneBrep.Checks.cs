using System;
using System.Collections.Generic;
using System.IO;

namespace Scene3D;

/// <summary>GrCis's consistency check of the corner table of <see cref="SceneBrep"/>.</summary>
public partial class SceneBrep
{
  /// <summary>
  /// Checks the corner table and writes one line per problem to <paramref name="errors"/> (null: standard output):
  /// triangles using a vertex twice, opposite corners that are not mutual or do not share their edge (or share it
  /// facing the other way). <paramref name="thorough"/> also walks around every vertex and checks that no edge has more
  /// than two triangles and that each shared edge is linked; it assumes a consistently oriented manifold.
  /// Returns the number of problems (0 for a line mesh).
  /// </summary>
  public int CheckCornerTable(StreamWriter? errors, bool thorough = false)
  {
    if (!HasTriangles)
      return 0;
    TextWriter output = errors ?? Console.Out;
    int count = 0;
    void Report(string message)
    {
      count++;
      output.WriteLine(message);
    }

    for (int c = 0; c < Corners; c += 3)
    {
      int a = vertexPtr[c], b = vertexPtr[c + 1], d = vertexPtr[c + 2];
      if (a == b || b == d || d == a)
        Report($"Triangle {c / 3} uses vertex {(a == b || a == d ? a : b)} twice");
    }

    for (int c = 0; c < Corners; c++)
    {
      int o = cOpposite(c);
      if (o == NULL)
        continue;
      if (cOpposite(o) != c)
        Report($"Corner {c} has opposite {o}, but {o} has opposite {cOpposite(o)}");
      else if (cVertex(cNext(c)) != cVertex(cPrev(o)) || cVertex(cPrev(c)) != cVertex(cNext(o)))
        Report(cVertex(cNext(c)) == cVertex(cNext(o)) && cVertex(cPrev(c)) == cVertex(cPrev(o))
          ? $"Opposite corners {c} and {o} share their edge but their triangles face opposite ways"
          : $"Opposite corners {c} and {o} do not share an edge");
    }

    if (thorough)
    {
      CheckFans(Report);
      CheckEdges(Report);
    }
    return count;
  }

  /// <summary>Walking right around the vertex of each corner visits corners of that vertex only, each once.</summary>
  void CheckFans(Action<string> report)
  {
    var visited = new HashSet<int>();
    for (int start = 0; start < Corners; start++)
    {
      visited.Clear();
      int c = start;
      while (true)
      {
        int o = cOpposite(cPrev(c));
        if (o == NULL)
          break;
        c = cPrev(o);
        if (c == start)
          break;
        if (cVertex(c) != cVertex(start))
        {
          report($"Walking around corner {start} reached corner {c} of another vertex");
          break;
        }
        if (!visited.Add(c))
        {
          report($"Walking around corner {start} reached corner {c} twice");
          break;
        }
      }
    }
  }

  /// <summary>Each edge has at most two triangles, and when two, their corners across it are linked.</summary>
  void CheckEdges(Action<string> report)
  {
    var first = new Dictionary<(int, int), (int Corner, int Uses)>();
    for (int c = 0; c < Corners; c++)
    {
      int a = cVertex(cNext(c)), b = cVertex(cPrev(c));
      var edge = a < b ? (a, b) : (b, a);
      if (!first.TryGetValue(edge, out var seen))
        first[edge] = (c, 1);
      else
      {
        if (seen.Uses == 1 && cOpposite(c) != seen.Corner)
          report($"Corners {seen.Corner} and {c} face the same edge but are not linked");
        else if (seen.Uses >= 2)
          report($"Corner {c} faces an edge that already has two triangles (not a 2-manifold)");
        first[edge] = (seen.Corner, seen.Uses + 1);
      }
    }
  }
}
