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

  public static SceneJson Of(SceneTessellation scene, RenderSettings settings, string name)
  {
    var shapes = new List<ShapeJson>();
    var shapeOf = new Dictionary<Vector3d[], int>(ReferenceEqualityComparer.Instance);
    var parts = new List<PartJson>();
    foreach (TessellatedPart part in scene.Parts)
    {
      if (part.TriangleCount == 0)
        continue;
      if (!shapeOf.TryGetValue(part.Positions, out int shape))
      {
        shapeOf[part.Positions] = shape = shapes.Count;
        shapes.Add(new ShapeJson(part.Positions.SelectMany(p => new[] { (float)p.X, (float)p.Y, (float)p.Z }).ToArray(), part.Indices));
      }
      parts.Add(new PartJson(part.Name, part.TypeName, part.Kind.ToString(), part.CsgOperation?.ToString(), V(part.BaseColor),
                             Rows(part.LocalToWorld), shape, EmissionOf(part.Node)));
    }
    LightJson[] lights = scene.Lights.Select(l => new LightJson(l.Kind.ToString(), V(l.Position), V(l.Intensity), V(l.EdgeU), V(l.EdgeV), l.Radius)).ToArray();
    CameraJson? camera = scene.Camera is TessellatedCamera c
      ? new CameraJson(V(c.Position), V(c.Direction), V(c.Up), c.VerticalFov, c.AspectRatio, c.Exact)
      : null;
    return new SceneJson(name, settings.Width, settings.Height, shapes.ToArray(), parts.ToArray(), lights, camera, scene.Notes);
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
