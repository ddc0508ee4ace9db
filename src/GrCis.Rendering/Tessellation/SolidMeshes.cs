using System;
using OpenTK.Mathematics;
using Scene3D;

namespace Rendering.Tessellation;

/// <summary>Triangles of each library solid in its own local space (see each solid's class for its shape).</summary>
internal static class SolidMeshes
{
  /// <summary>The unit sphere: a UV grid, vertices on the surface, poles on ±z.</summary>
  public static TriangleBuilder Sphere(int segments, int rings, out double tolerance)
  {
    var b = new TriangleBuilder();
    // The poles exactly (sin π is not 0 in doubles), so the cells around them lose their degenerate halves.
    b.Grid(rings, segments, (v, u) => v == 0.0 ? Vector3d.UnitZ : v == 1.0 ? -Vector3d.UnitZ : Polar(Math.PI * v, 2.0 * Math.PI * u), p => p);
    tolerance = ChordError(Math.Max(Math.PI / rings, 2.0 * Math.PI / segments));
    return b;
  }

  static Vector3d Polar(double theta, double phi) =>
    new(Math.Sin(theta) * Math.Cos(phi), Math.Sin(theta) * Math.Sin(phi), Math.Cos(theta));

  /// <summary>Largest distance between a unit circle and a polygon of steps <paramref name="step"/> (radians), doubled for the diagonal of a grid cell.</summary>
  static double ChordError(double step) => 1.0 - Math.Cos(step);

  /// <summary>The unit cube [0, 1]³.</summary>
  public static TriangleBuilder Cube() => Box(Vector3d.Zero, Vector3d.One);

  /// <summary>The unit-radius cylinder about z between <paramref name="z0"/> and <paramref name="z1"/>, with flat caps when <paramref name="caps"/>.</summary>
  public static TriangleBuilder Cylinder(double z0, double z1, bool caps, int segments, out double tolerance)
  {
    var b = new TriangleBuilder();
    b.Grid(1, segments, (v, u) => Ring(2.0 * Math.PI * u, z0 + v * (z1 - z0)), p => new Vector3d(p.X, p.Y, 0.0));
    if (caps)
      foreach ((double z, double side) in new[] { (z0, -1.0), (z1, 1.0) })
      {
        int c = b.Add(new Vector3d(0.0, 0.0, z));
        int first = -1, previous = -1;
        for (int j = 0; j < segments; j++)
        {
          int k = b.Add(Ring(2.0 * Math.PI * j / segments, z));
          if (previous >= 0)
            b.Triangle(c, previous, k, new Vector3d(0.0, 0.0, side));
          else
            first = k;
          previous = k;
        }
        b.Triangle(c, previous, first, new Vector3d(0.0, 0.0, side));
      }
    tolerance = ChordError(Math.PI / segments);
    return b;
  }

  static Vector3d Ring(double phi, double z) => new(Math.Cos(phi), Math.Sin(phi), z);

  /// <summary>The torus about z: tube radius <paramref name="r"/> around the circle of radius <paramref name="big"/>.</summary>
  public static TriangleBuilder Torus(double big, double r, int segments, int tubeSegments, out double tolerance)
  {
    var b = new TriangleBuilder();
    b.Grid(tubeSegments, segments, (v, u) =>
    {
      double phi = 2.0 * Math.PI * u, theta = 2.0 * Math.PI * v;
      double d = big + r * Math.Cos(theta);
      return new Vector3d(d * Math.Cos(phi), d * Math.Sin(phi), r * Math.Sin(theta));
    }, p =>
    {
      double len = Math.Sqrt(p.X * p.X + p.Y * p.Y);
      Vector3d axis = len > 0.0 ? new Vector3d(p.X / len * big, p.Y / len * big, 0.0) : Vector3d.Zero;
      return p - axis;
    });
    tolerance = (big + r) * ChordError(2.0 * Math.PI / segments) + r * ChordError(2.0 * Math.PI / tubeSegments);
    return b;
  }

  /// <summary>A rectangle [x0, x1] × [y0, y1] of the plane z = 0, facing +z.</summary>
  public static TriangleBuilder Rectangle(double x0, double x1, double y0, double y1)
  {
    var b = new TriangleBuilder();
    int a = b.Add(new Vector3d(x0, y0, 0.0)), c = b.Add(new Vector3d(x1, y0, 0.0));
    int d = b.Add(new Vector3d(x1, y1, 0.0)), e = b.Add(new Vector3d(x0, y1, 0.0));
    b.Triangle(a, c, d, Vector3d.UnitZ);
    b.Triangle(a, d, e, Vector3d.UnitZ);
    return b;
  }

  /// <summary>A triangle of the plane z = 0, facing +z.</summary>
  public static TriangleBuilder FlatTriangle(Vector3d p0, Vector3d p1, Vector3d p2)
  {
    var b = new TriangleBuilder();
    b.Triangle(b.Add(p0), b.Add(p1), b.Add(p2), Vector3d.UnitZ);
    return b;
  }

  /// <summary>Each patch of <paramref name="surface"/> as a grid of <paramref name="steps"/> × <paramref name="steps"/> cells, facing ∂S/∂u × ∂S/∂v.</summary>
  public static TriangleBuilder Bezier(BezierSurface surface, int steps)
  {
    var b = new TriangleBuilder();
    for (int patch = 0; patch < surface.Patches; patch++)
    {
      int pi = patch;
      b.Grid(steps, steps, (v, u) =>
      {
        surface.Evaluate(pi, u, v, out Vector3d s, out _, out _);
        return s;
      }, _ => Vector3d.Zero);
    }
    return b;
  }

  /// <summary>A triangle mesh's own triangles, in its order.</summary>
  public static TriangleBuilder Mesh(SceneBrep mesh)
  {
    var b = new TriangleBuilder();
    for (int v = 0; v < mesh.Vertices; v++)
    {
      Vector3 p = mesh.GetVertex(v);
      b.Add(new Vector3d(p.X, p.Y, p.Z));
    }
    for (int t = 0; t < mesh.Triangles; t++)
    {
      mesh.GetTriangleVertices(t, out int a, out int c, out int d);
      b.TriangleAsIs(a, c, d);
    }
    return b;
  }

  /// <summary>The box [c1, c2] (a script's own solid stands as its bounding box).</summary>
  public static TriangleBuilder Box(Vector3d c1, Vector3d c2)
  {
    var b = new TriangleBuilder();
    var center = 0.5 * (c1 + c2);
    for (int k = 0; k < 8; k++)
      b.Add(new Vector3d((k & 1) == 0 ? c1.X : c2.X, (k & 2) == 0 ? c1.Y : c2.Y, (k & 4) == 0 ? c1.Z : c2.Z));
    int[][] faces = [[0, 2, 6, 4], [1, 3, 7, 5], [0, 1, 5, 4], [2, 3, 7, 6], [0, 1, 3, 2], [4, 5, 7, 6]];
    Vector3d[] p = b.Positions;
    foreach (int[] f in faces)
    {
      Vector3d faceCenter = (p[f[0]] + p[f[1]] + p[f[2]] + p[f[3]]) / 4.0;
      b.Triangle(f[0], f[1], f[2], faceCenter - center);
      b.Triangle(f[0], f[2], f[3], faceCenter - center);
    }
    return b;
  }
}
