using System;
using System.Collections.Generic;
using System.Linq;
using GrCis.Hosting;
using OpenTK.Mathematics;
using Rendering.Tessellation;

namespace GrCis.Studio;

/// <summary>
/// The scene on show as the page's 3D view draws it (<c>GET /api/scene/tessellation</c>): each solid's triangles with its
/// transform and colour, the lights and the camera, in GrCis's own (left-handed) world; the page mirrors it into three.js.
/// Solids of one shape share one entry of <see cref="SceneJson.Shapes"/>, so a scene of many equal spheres stays small.
/// </summary>
internal static class SceneView3d
{
  /// <summary>
  /// The scene: its name, the render's size (the camera's aspect ratio), the shapes (local triangles), the parts that place
  /// them, the lights, the camera (null when the scene has none) and what could not be shown as it is.
  /// </summary>
  internal sealed record SceneJson(string Name, int Width, int Height, ShapeJson[] Shapes, PartJson[] Parts, LightJson[] Lights, CameraJson? Camera,
                                   IReadOnlyList<string> Notes);

  /// <summary>Vertex positions in the solid's local space (x, y, z, …) and three vertex indices per triangle.</summary>
  internal sealed record ShapeJson(float[] Positions, int[] Indices);

  /// <summary>
  /// One solid: its name (<c>Sphere 3</c>), class, kind (<c>Surface</c>, or <c>BoundingBox</c> for a script's own solid),
  /// the CSG operation it is an operand of (null under unions only), linear RGB colour, local-to-world matrix (16 numbers,
  /// row by row, GrCis's row vectors: as three.js's <c>Matrix4.fromArray</c> reads a column-vector matrix column by
  /// column, the same 16 numbers), its index into <see cref="SceneJson.Shapes"/>, and the radiance it emits (a
  /// <see cref="Rendering.PhongMaterial.Emission"/>: a light the path tracers see) or null.
  /// </summary>
  internal sealed record PartJson(string Name, string Type, string Kind, string? Csg, double[] Color, double[] Matrix, int Shape, double[]? Emission);

  /// <summary>A light: kind (<c>Point</c>, <c>Rectangle</c>, <c>Sphere</c>), centre, intensity per band, a rectangle's edges, a sphere's radius.</summary>
  internal sealed record LightJson(string Kind, double[] Position, double[] Intensity, double[] EdgeU, double[] EdgeV, double Radius);

  /// <summary>The camera as a pinhole: position, unit direction and up, vertical field of view (radians), width / height; exact = the camera's own values.</summary>
  internal sealed record CameraJson(double[] Position, double[] Direction, double[] Up, double VerticalFov, double Aspect, bool Exact);

  /// <summary>
  /// The most triangles the view is sent (about 20 MB of JSON, which a page parses and draws in a few seconds): the
  /// largest shapes beyond it are sent as their boxes, with a note, so a million-triangle mesh never freezes the page.
  /// </summary>
  public const int TriangleBudget = 500_000;

  public static SceneJson Of(SceneTessellation scene, RenderSettings settings, string name, int triangleBudget = TriangleBudget)
  {
    // The shapes, each once, and which of them fit in the budget (the smallest first, so one huge mesh, not the many
    // small solids around it, becomes a box).
    var unique = new List<TessellatedPart>();
    var seen = new HashSet<Vector3d[]>(ReferenceEqualityComparer.Instance);
    foreach (TessellatedPart part in Shown(scene))
      if (seen.Add(part.Positions))
        unique.Add(part);
    var boxed = new HashSet<Vector3d[]>(ReferenceEqualityComparer.Instance);
    long sent = 0;
    foreach (TessellatedPart part in unique.OrderBy(p => p.TriangleCount))
      if ((sent += part.TriangleCount) > triangleBudget)
        boxed.Add(part.Positions);

    var notes = new List<string>(scene.Notes);
    var shapes = new List<ShapeJson>();
    var shapeOf = new Dictionary<Vector3d[], int>(ReferenceEqualityComparer.Instance);
    var parts = new List<PartJson>();
    foreach (TessellatedPart part in Shown(scene))
    {
      bool box = boxed.Contains(part.Positions);
      if (!shapeOf.TryGetValue(part.Positions, out int shape))
      {
        shapeOf[part.Positions] = shape = shapes.Count;
        shapes.Add(box ? BoxOf(part.Positions) : new ShapeJson(part.Positions.SelectMany(p => new[] { (float)p.X, (float)p.Y, (float)p.Z }).ToArray(), part.Indices));
        if (box)
          notes.Add($"{part.Name}: {part.TriangleCount:N0} triangles, shown as its box (the 3D view draws at most {triangleBudget:N0})");
      }
      parts.Add(new PartJson(part.Name, part.TypeName, box ? nameof(PartKind.BoundingBox) : part.Kind.ToString(), part.CsgOperation?.ToString(),
                             V(part.BaseColor), Rows(part.LocalToWorld), shape, EmissionOf(part.Node)));
    }
    LightJson[] lights = scene.Lights.Select(l => new LightJson(l.Kind.ToString(), V(l.Position), V(l.Intensity), V(l.EdgeU), V(l.EdgeV), l.Radius)).ToArray();
    CameraJson? camera = scene.Camera is TessellatedCamera c
      ? new CameraJson(V(c.Position), V(c.Direction), V(c.Up), c.VerticalFov, c.AspectRatio, c.Exact)
      : null;
    return new SceneJson(name, settings.Width, settings.Height, shapes.ToArray(), parts.ToArray(), lights, camera, notes);
  }

  /// <summary>The parts the view is sent, in the order of <see cref="SceneJson.Parts"/> (those with triangles): <see cref="SceneParts"/> indexes the same list.</summary>
  internal static IEnumerable<TessellatedPart> Shown(SceneTessellation scene)
  {
    foreach (TessellatedPart part in scene.Parts)
      if (part.TriangleCount > 0)
        yield return part;
  }

  // The box around a shape's vertices (in its local space), as 12 triangles.
  static ShapeJson BoxOf(Vector3d[] positions)
  {
    Vector3d lo = positions[0], hi = positions[0];
    foreach (Vector3d p in positions)
    {
      lo = Vector3d.ComponentMin(lo, p);
      hi = Vector3d.ComponentMax(hi, p);
    }
    var corners = new float[24];
    for (int k = 0; k < 8; k++)
    {
      corners[3 * k] = (float)((k & 1) == 0 ? lo.X : hi.X);
      corners[3 * k + 1] = (float)((k & 2) == 0 ? lo.Y : hi.Y);
      corners[3 * k + 2] = (float)((k & 4) == 0 ? lo.Z : hi.Z);
    }
    // Two triangles per face of the cube whose corner k has bits (x, y, z).
    int[] faces = [0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5];
    return new ShapeJson(corners, faces);
  }

  // An emissive surface is a light of the scene (the Cornell box's only one), drawn glowing.
  static double[]? EmissionOf(Rendering.ISceneNode node)
  {
    if (node.GetAttribute(Rendering.PropertyName.MATERIAL) is not Rendering.PhongMaterial { Emission: { Length: > 0 } e })
      return null;
    // One band is grey, as the renderer reads it.
    return [e[0], e[Math.Min(1, e.Length - 1)], e[Math.Min(2, e.Length - 1)]];
  }

  static double[] V(Vector3d v) => [v.X, v.Y, v.Z];

  static double[] Rows(Matrix4d m) =>
    [m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24, m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44];
}
