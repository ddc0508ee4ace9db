using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// The emissive surfaces <see cref="PathTracing"/> samples directly (next-event estimation), each a solid whose
/// material has an <see cref="PhongMaterial.Emission"/> and that only unions lie above, so every point of it is
/// really there: bounded rectangles (<see cref="Plane"/>), sampled uniformly by area, and spheres
/// (<see cref="Sphere"/>) placed by a similarity (rotation, uniform scale, translation), sampled uniformly in the
/// cone of directions they subtend. Other emissive solids still light the scene, found by the rays that hit them.
/// Each is an <see cref="ILight"/> (<see cref="EmissiveRectangle"/>, <see cref="EmissiveSphere"/>); <see cref="SceneLights"/> adds them to the scene's other lights.
/// </summary>
internal sealed class EmitterSet
{
  readonly List<(ISolid Solid, ILight Light)> found;
  readonly LightSampler sampler;
  readonly Dictionary<ISolid, ILight> index = new(ReferenceEqualityComparer.Instance);

  public static readonly EmitterSet Empty = new(new List<(ISolid, ILight)>());

  EmitterSet(List<(ISolid Solid, ILight Light)> found)
  {
    this.found = found;
    var lights = new List<ILight>(found.Count);
    foreach (var (solid, light) in found)
    {
      lights.Add(light);
      index[solid] = light;
    }
    sampler = new LightSampler(lights);
  }

  public int Count => sampler.Count;

  /// <summary>The emissive solids found and their lights (for <see cref="SceneLights"/>).</summary>
  public IReadOnlyList<(ISolid Solid, ILight Light)> Lights => found;

  /// <summary>
  /// A light sample seen from <paramref name="x"/>: <paramref name="pick"/> chooses the emitter (by power), (u, v) the
  /// point or direction on it. Gives the vector <paramref name="toLight"/> to the emitter's surface, its length, the
  /// unit direction, the radiance coming along it and the density per solid angle (pick included); false when the
  /// chosen emitter sends nothing to <paramref name="x"/> (seen from behind, or <paramref name="x"/> inside a sphere).
  /// </summary>
  public bool Sample(in Vector3d x, double pick, double u, double v,
    out Vector3d toLight, out double dist, out Vector3d wi, out Rgb radiance, out double pdf)
  {
    toLight = wi = default;
    dist = pdf = 0.0;
    radiance = Rgb.Zero;
    ILight? light = sampler.Sample(pick, out double probability);
    if (light == null || !light.SampleLi(new LightContext(x, Vector3d.Zero, null), u, v, out LightSample s))
      return false;
    toLight = s.ToLight;
    dist = s.Distance;
    wi = s.Wi;
    radiance = s.L;
    pdf = probability * s.Pdf;
    return true;
  }

  /// <summary>
  /// The density per solid angle with which <see cref="Sample"/> from <paramref name="origin"/> gives the ray that
  /// hit <paramref name="solid"/> at <paramref name="x"/> (normal <paramref name="normal"/>) along the unit
  /// <paramref name="direction"/>; false when the solid is not sampled here.
  /// </summary>
  public bool Pdf(ISolid? solid, in Vector3d origin, in Vector3d x, in Vector3d normal, in Vector3d direction, out double pdf)
  {
    pdf = 0.0;
    if (solid == null || !index.TryGetValue(solid, out ILight? light))
      return false;
    pdf = sampler.Probability(light) * light.PdfLi(new LightContext(origin, Vector3d.Zero, null), direction, x, normal);
    return true;
  }

  /// <summary>The emitters of the scene under <paramref name="root"/>, in their current placement.</summary>
  public static EmitterSet Of(IIntersectable? root)
  {
    var found = new List<(ISolid, ILight)>();
    if (root is ISceneNode node)
      Collect(node, found);
    return found.Count == 0 ? Empty : new EmitterSet(found);
  }

  static void Collect(ISceneNode node, List<(ISolid, ILight)> found)
  {
    if (node is CSGInnerNode csg && csg.Operation != SetOperation.Union)
      return;   // an intersection or difference may cut the surface: leave it to the rays that hit it
    if (node is Plane plane && !plane.Triangle && SubclassCheck.KeepsGeometry(plane, typeof(Plane)) &&
        double.IsFinite(plane.XMin) && double.IsFinite(plane.XMax) && double.IsFinite(plane.YMin) && double.IsFinite(plane.YMax) &&
        EmissionOf(plane) is Rgb radiance)
    {
      Matrix4d toWorld = plane.ToWorld();
      Vector3d a = Vector3d.TransformPosition(new Vector3d(plane.XMin, plane.YMin, 0.0), toWorld);
      Vector3d b = Vector3d.TransformPosition(new Vector3d(plane.XMax, plane.YMin, 0.0), toWorld);
      Vector3d c = Vector3d.TransformPosition(new Vector3d(plane.XMin, plane.YMax, 0.0), toWorld);
      Vector3d normal = Vector3d.TransformNormalInverse(Vector3d.UnitZ, toWorld.Inverted()).Normalized();
      if (Vector3d.Cross(b - a, c - a).LengthSquared > 0.0)
        found.Add((plane, new EmissiveRectangle(a, b - a, c - a, normal, radiance)));
    }
    else if (node is Sphere sphere && SubclassCheck.KeepsGeometry(sphere, typeof(Sphere)) && EmissionOf(sphere) is Rgb glow &&
             Similarity(sphere.ToWorld(), out double scale))
    {
      Vector3d centre = Vector3d.TransformPosition(Vector3d.Zero, sphere.ToWorld());
      found.Add((sphere, new EmissiveSphere(centre, scale, glow)));
    }
    foreach (ISceneNode child in node.Children)
      Collect(child, found);
  }

  /// <summary>The radiance of an emissive material on <paramref name="node"/>, null when it emits nothing.</summary>
  static Rgb? EmissionOf(ISceneNode node)
  {
    if (node.GetAttribute(PropertyName.MATERIAL) is PhongMaterial { Emission: double[] emission } && emission.Length > 0)
    {
      Rgb radiance = Rgb.From(emission);
      if (radiance.Average > 0.0)
        return radiance;
    }
    return null;
  }

  /// <summary>
  /// True when <paramref name="m"/> maps the unit sphere to a sphere (its linear part is a rotation, possibly
  /// mirrored, times a uniform <paramref name="scale"/>): the images of the axes are orthogonal and equally long.
  /// </summary>
  internal static bool Similarity(in Matrix4d m, out double scale)
  {
    Vector3d x = m.Row0.Xyz, y = m.Row1.Xyz, z = m.Row2.Xyz;
    double xx = x.LengthSquared, yy = y.LengthSquared, zz = z.LengthSquared;
    double s2 = (xx + yy + zz) / 3.0;
    scale = Math.Sqrt(s2);
    // Relative to s²: what a chain of rotations and scales leaves in doubles, far below any visible non-uniformity.
    double tolerance = 1e-9 * s2;
    return s2 > 0.0 && double.IsFinite(s2) &&
           Math.Abs(xx - s2) <= tolerance && Math.Abs(yy - s2) <= tolerance && Math.Abs(zz - s2) <= tolerance &&
           Math.Abs(Vector3d.Dot(x, y)) <= tolerance && Math.Abs(Vector3d.Dot(y, z)) <= tolerance && Math.Abs(Vector3d.Dot(z, x)) <= tolerance;
  }
}
