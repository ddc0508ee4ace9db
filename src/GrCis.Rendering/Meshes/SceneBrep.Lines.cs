using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Scene3D;

/// <summary>GrCis's line mode of <see cref="SceneBrep"/> (wireframes, curves) and random vertex colours.</summary>
public partial class SceneBrep
{
  /// <summary>True once the mesh holds lines; then vertex pairs, not triples, follow each other in <c>vertexPtr</c>.</summary>
  protected bool lines;

  /// <summary>True while the mesh can take lines: it holds lines or nothing yet.</summary>
  public bool HasLines => lines || vertexPtr.Count == 0;

  /// <summary>True while the mesh can take triangles: it holds triangles or nothing yet.</summary>
  public bool HasTriangles => !lines || vertexPtr.Count == 0;

  /// <summary>Number of lines; 0 when the mesh holds triangles.</summary>
  public int Lines => lines ? vertexPtr.Count / 2 : 0;

  /// <summary>Width of the lines when drawn (pixels).</summary>
  public float LineWidth { get; set; } = 2.0f;

  /// <summary>Adds a line between two vertices and returns its handle; <see cref="NULL"/> when the mesh holds triangles.</summary>
  public int AddLine(int v1, int v2)
  {
    if (!HasLines)
      return NULL;
    CheckVertex(v1);
    CheckVertex(v2);
    lines = true;
    vertexPtr.Add(v1);
    vertexPtr.Add(v2);
    return vertexPtr.Count / 2 - 1;
  }

  /// <summary>The two vertices of line <paramref name="li"/>.</summary>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="li"/> is not a line of the mesh.</exception>
  public void GetLineVertices(int li, out int v1, out int v2)
  {
    if ((uint)li >= (uint)Lines)
      throw new ArgumentOutOfRangeException(nameof(li), li, $"Line handle must be in [0, {Lines}).");
    v1 = vertexPtr[2 * li];
    v2 = vertexPtr[2 * li + 1];
  }

  /// <summary>Gives every vertex without a colour a random one (each channel uniform in [0, 1)), reproducibly from <paramref name="seed"/>.</summary>
  public void GenerateColors(int seed)
  {
    var rnd = new Random(seed);
    colors ??= new List<Vector3>(geometry.Capacity);
    while (colors.Count < geometry.Count)
      colors.Add(new Vector3((float)rnd.NextDouble(), (float)rnd.NextDouble(), (float)rnd.NextDouble()));
  }
}
