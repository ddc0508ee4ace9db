using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering.Tessellation;

/// <summary>Collects vertices and triangles, turning each triangle to face a given outward direction and dropping degenerate ones.</summary>
internal sealed class TriangleBuilder
{
  readonly List<Vector3d> positions = new();
  readonly List<int> indices = new();

  public int Add(Vector3d p)
  {
    positions.Add(p);
    return positions.Count - 1;
  }

  /// <summary>Adds triangle (a, b, c) so that its normal <c>Cross(b - a, c - a)</c> has a positive dot product with <paramref name="outward"/>.</summary>
  public void Triangle(int a, int b, int c, Vector3d outward)
  {
    Vector3d n = Vector3d.Cross(positions[b] - positions[a], positions[c] - positions[a]);
    // Pole triangles of a UV grid have two equal corners: nothing to draw.
    if (n.LengthSquared == 0.0)
      return;
    if (Vector3d.Dot(n, outward) < 0.0)
      (b, c) = (c, b);
    indices.Add(a);
    indices.Add(b);
    indices.Add(c);
  }

  /// <summary>Adds triangle (a, b, c) in the given order.</summary>
  public void TriangleAsIs(int a, int b, int c)
  {
    indices.Add(a);
    indices.Add(b);
    indices.Add(c);
  }

  /// <summary>
  /// A grid of (rows + 1) × (columns + 1) points <paramref name="point"/>(i / rows, j / columns), two triangles per cell,
  /// each facing <paramref name="outward"/> at its centroid.
  /// </summary>
  public void Grid(int rows, int columns, Func<double, double, Vector3d> point, Func<Vector3d, Vector3d> outward)
  {
    int first = positions.Count;
    for (int i = 0; i <= rows; i++)
      for (int j = 0; j <= columns; j++)
        Add(point(i / (double)rows, j / (double)columns));
    int stride = columns + 1;
    for (int i = 0; i < rows; i++)
      for (int j = 0; j < columns; j++)
      {
        int a = first + i * stride + j, b = a + 1, c = a + stride, d = c + 1;
        Triangle(a, b, d, outward((positions[a] + positions[b] + positions[d]) / 3.0));
        Triangle(a, d, c, outward((positions[a] + positions[d] + positions[c]) / 3.0));
      }
  }

  public Vector3d[] Positions => positions.ToArray();

  public int[] Indices => indices.ToArray();
}
