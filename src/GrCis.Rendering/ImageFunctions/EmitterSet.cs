using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The emissive surfaces <see cref="PathTracing"/> samples directly (next-event estimation): bounded
/// rectangles (<see cref="Plane"/>) whose material has an <see cref="PhongMaterial.Emission"/> and that only
/// unions lie above, so every point of the rectangle is really there. Other emissive solids still light the
/// scene, found by the rays that hit them. One is picked in proportion to its power (area × mean radiance),
/// then a point uniformly on it.
/// </summary>
internal sealed class EmitterSet
{
  readonly struct Emitter
  {
    public readonly Vector3d Corner, Edge1, Edge2, Normal;
    public readonly Rgb Radiance;
    public readonly double PdfArea;

    public Emitter(Vector3d corner, Vector3d edge1, Vector3d edge2, Vector3d normal, Rgb radiance, double pdfArea)
    {
      Corner = corner;
      Edge1 = edge1;
      Edge2 = edge2;
      Normal = normal;
      Radiance = radiance;
      PdfArea = pdfArea;
    }
  }

  readonly Emitter[] emitters;
  readonly double[] cdf;
  readonly Dictionary<ISolid, double> pdfArea = new(ReferenceEqualityComparer.Instance);

  public static readonly EmitterSet Empty = new(Array.Empty<(ISolid, Vector3d, Vector3d, Vector3d, Vector3d, Rgb)>());

  EmitterSet((ISolid Solid, Vector3d Corner, Vector3d Edge1, Vector3d Edge2, Vector3d Normal, Rgb Radiance)[] found)
  {
    // cdf holds the running power (area × mean radiance) first, then is divided by the total.
    cdf = new double[found.Length];
    double total = 0.0;
    for (int k = 0; k < found.Length; k++)
      cdf[k] = total += Vector3d.Cross(found[k].Edge1, found[k].Edge2).Length * found[k].Radiance.Average;
    emitters = new Emitter[found.Length];
    for (int k = 0; k < found.Length; k++)
    {
      var f = found[k];
      cdf[k] /= total;
      // Picked with probability power/total, then uniform over the area: density mean radiance / total per unit area.
      double density = f.Radiance.Average / total;
      emitters[k] = new Emitter(f.Corner, f.Edge1, f.Edge2, f.Normal, f.Radiance, density);
      pdfArea[f.Solid] = density;
    }
  }

  public int Count => emitters.Length;

  /// <summary>True when <paramref name="solid"/> is sampled here; <paramref name="density"/> is its density per unit area.</summary>
  public bool Contains(ISolid? solid, out double density)
  {
    density = 0.0;
    return solid != null && pdfArea.TryGetValue(solid, out density);
  }

  /// <summary>A point of an emitter: <paramref name="pick"/> chooses the emitter, (u, v) the point on it.</summary>
  public void Sample(double pick, double u, double v, out Vector3d point, out Vector3d normal, out Rgb radiance, out double density)
  {
    int k = Array.BinarySearch(cdf, pick);
    k = k < 0 ? ~k : k;
    k = Math.Min(k, emitters.Length - 1);
    ref readonly Emitter e = ref emitters[k];
    point = e.Corner + u * e.Edge1 + v * e.Edge2;
    normal = e.Normal;
    radiance = e.Radiance;
    density = e.PdfArea;
  }

  /// <summary>The emitters of the scene under <paramref name="root"/>, in their current placement.</summary>
  public static EmitterSet Of(IIntersectable? root)
  {
    var found = new List<(ISolid, Vector3d, Vector3d, Vector3d, Vector3d, Rgb)>();
    if (root is ISceneNode node)
      Collect(node, found);
    return found.Count == 0 ? Empty : new EmitterSet(found.ToArray());
  }

  static void Collect(ISceneNode node, List<(ISolid, Vector3d, Vector3d, Vector3d, Vector3d, Rgb)> found)
  {
    if (node is CSGInnerNode csg && csg.Operation != SetOperation.Union)
      return;   // an intersection or difference may cut the rectangle: leave it to the rays that hit it
    if (node is Plane plane && !plane.Triangle && SubclassCheck.KeepsGeometry(plane, typeof(Plane)) &&
        double.IsFinite(plane.XMin) && double.IsFinite(plane.XMax) && double.IsFinite(plane.YMin) && double.IsFinite(plane.YMax) &&
        plane.GetAttribute(PropertyName.MATERIAL) is PhongMaterial { Emission: double[] emission } && emission.Length > 0)
    {
      Rgb radiance = Rgb.From(emission);
      if (radiance.Average > 0.0)
      {
        Matrix4d toWorld = plane.ToWorld();
        Vector3d a = Vector3d.TransformPosition(new Vector3d(plane.XMin, plane.YMin, 0.0), toWorld);
        Vector3d b = Vector3d.TransformPosition(new Vector3d(plane.XMax, plane.YMin, 0.0), toWorld);
        Vector3d c = Vector3d.TransformPosition(new Vector3d(plane.XMin, plane.YMax, 0.0), toWorld);
        Vector3d normal = Vector3d.TransformNormalInverse(Vector3d.UnitZ, toWorld.Inverted()).Normalized();
        if (Vector3d.Cross(b - a, c - a).LengthSquared > 0.0)
          found.Add((plane, a, b - a, c - a, normal, radiance));
      }
    }
    foreach (ISceneNode child in node.Children)
      Collect(child, found);
  }
}
