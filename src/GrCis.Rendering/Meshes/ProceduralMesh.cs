using Scene3D;
using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>Meshes generated in code (benchmarks and tests: no big files in the repository).</summary>
public static class ProceduralMesh
{
  /// <summary>
  /// A closed torus about the z axis (radii <paramref name="bigRadius"/>, <paramref name="smallRadius"/>),
  /// <paramref name="segments"/> × <paramref name="rings"/> quads = 2·segments·rings triangles, faces
  /// oriented outwards ((b − a) × (c − a)), with vertex normals.
  /// </summary>
  public static SceneBrep Torus(int segments, int rings, double bigRadius = 1.0, double smallRadius = 0.4)
  {
    if (segments < 3 || rings < 3)
      throw new ArgumentOutOfRangeException(nameof(segments), $"a torus needs at least 3 segments and 3 rings (got {segments} × {rings})");
    var mesh = new SceneBrep();
    mesh.Reserve(segments * rings);
    for (int i = 0; i < segments; i++)
    {
      double u = 2.0 * Math.PI * i / segments;
      for (int j = 0; j < rings; j++)
      {
        double v = 2.0 * Math.PI * j / rings;
        var n = new Vector3d(Math.Cos(v) * Math.Cos(u), Math.Cos(v) * Math.Sin(u), Math.Sin(v));
        double rho = bigRadius + smallRadius * Math.Cos(v);
        var p = new Vector3d(rho * Math.Cos(u), rho * Math.Sin(u), smallRadius * Math.Sin(v));
        int vi = mesh.AddVertex((Vector3)p);
        mesh.SetNormal(vi, (Vector3)n);
      }
    }
    for (int i = 0; i < segments; i++)
    {
      int i1 = (i + 1) % segments;
      for (int j = 0; j < rings; j++)
      {
        int j1 = (j + 1) % rings;
        int a = i * rings + j, b = i1 * rings + j, c = i1 * rings + j1, d = i * rings + j1;
        mesh.AddTriangle(a, b, c);
        mesh.AddTriangle(a, c, d);
      }
    }
    return mesh;
  }

  /// <summary>The torus with about <paramref name="triangles"/> triangles (segments = 2 · rings).</summary>
  public static SceneBrep TorusWithTriangles(int triangles)
  {
    int rings = Math.Max(3, (int)Math.Round(Math.Sqrt(triangles / 4.0)));
    return Torus(2 * rings, rings);
  }
}
