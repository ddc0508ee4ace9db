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
/// One emitter is picked in proportion to its power (area × mean radiance), then a point or direction on it.
/// </summary>
internal sealed class EmitterSet
{
  readonly struct Emitter
  {
    // A rectangle: Corner + u·Edge1 + v·Edge2; a sphere (Radius > 0): centre Corner.
    public readonly Vector3d Corner, Edge1, Edge2, Normal;
    public readonly double Radius;
    public readonly Rgb Radiance;

    // A rectangle: probability of the pick per unit area; a sphere: probability of the pick.
    public readonly double Density;

    public Emitter(Vector3d corner, Vector3d edge1, Vector3d edge2, Vector3d normal, double radius, Rgb radiance, double density)
    {
      Corner = corner;
      Edge1 = edge1;
      Edge2 = edge2;
      Normal = normal;
      Radius = radius;
      Radiance = radiance;
      Density = density;
    }

    public double Area => Radius > 0.0 ? 4.0 * Math.PI * Radius * Radius : Vector3d.Cross(Edge1, Edge2).Length;

    public Emitter WithDensity(double density) => new(Corner, Edge1, Edge2, Normal, Radius, Radiance, density);
  }

  /// <summary>
  /// Points whose squared distance from a sphere's centre is within this relative margin of r² count as on it:
  /// they see none of its outer side, so they get no light sample and its rays no MIS weight against one.
  /// </summary>
  const double OnSphere = 1e-9;

  readonly Emitter[] emitters;
  readonly double[] cdf;
  readonly Dictionary<ISolid, int> index = new(ReferenceEqualityComparer.Instance);

  public static readonly EmitterSet Empty = new(new List<(ISolid, Emitter)>());

  EmitterSet(List<(ISolid Solid, Emitter Emitter)> found)
  {
    // cdf holds the running power (area × mean radiance) first, then is divided by the total.
    cdf = new double[found.Count];
    double total = 0.0;
    for (int k = 0; k < found.Count; k++)
      cdf[k] = total += found[k].Emitter.Area * found[k].Emitter.Radiance.Average;
    emitters = new Emitter[found.Count];
    for (int k = 0; k < found.Count; k++)
    {
      var (solid, e) = found[k];
      cdf[k] /= total;
      // Picked with probability power/total; a rectangle then uniformly over its area: mean radiance / total per unit area.
      double density = e.Radius > 0.0 ? e.Area * e.Radiance.Average / total : e.Radiance.Average / total;
      emitters[k] = e.WithDensity(density);
      index[solid] = k;
    }
  }

  public int Count => emitters.Length;

  /// <summary>
  /// A light sample seen from <paramref name="x"/>: <paramref name="pick"/> chooses the emitter, (u, v) the point
  /// or direction on it. Gives the vector <paramref name="toLight"/> to the emitter's surface, its length, the unit
  /// direction, the radiance coming along it and the density per solid angle (pick included); false when the
  /// chosen emitter sends nothing to <paramref name="x"/> (seen from behind, or <paramref name="x"/> inside a sphere).
  /// </summary>
  public bool Sample(in Vector3d x, double pick, double u, double v,
    out Vector3d toLight, out double dist, out Vector3d wi, out Rgb radiance, out double pdf)
  {
    int k = 0;
    if (emitters.Length > 1)
    {
      k = Array.BinarySearch(cdf, pick);
      k = Math.Min(k < 0 ? ~k : k, emitters.Length - 1);
    }
    ref readonly Emitter e = ref emitters[k];
    radiance = e.Radiance;
    pdf = 0.0;
    wi = default;
    if (e.Radius > 0.0)
    {
      dist = 0.0;
      toLight = default;
      if (!Cone(e, x, out Vector3d axis, out double cosMax, out double solidAngle))
        return false;
      // A direction uniform in the cone, then the near side of the sphere along it.
      wi = SampleWarp.UniformCone(u, v, axis, cosMax);
      Vector3d toCentre = e.Corner - x;
      double b = Vector3d.Dot(wi, toCentre);
      double miss = (toCentre - b * wi).LengthSquared;   // squared distance of the ray from the centre
      dist = b - Math.Sqrt(Math.Max(0.0, e.Radius * e.Radius - miss));
      toLight = wi * dist;
      pdf = e.Density / solidAngle;
      return dist > 1e-9;
    }
    toLight = e.Corner + u * e.Edge1 + v * e.Edge2 - x;
    double dist2 = toLight.LengthSquared;
    dist = Math.Sqrt(dist2);
    if (dist <= 1e-9)
      return false;
    wi = toLight / dist;
    double cosL = -Vector3d.Dot(e.Normal, wi);
    if (cosL <= 0.0)
      return false;
    pdf = e.Density * dist2 / cosL;
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
    if (solid == null || !index.TryGetValue(solid, out int k))
      return false;
    ref readonly Emitter e = ref emitters[k];
    if (e.Radius > 0.0)
    {
      if (Cone(e, origin, out _, out _, out double solidAngle))
        pdf = e.Density / solidAngle;
      return true;
    }
    double cosL = -Vector3d.Dot(normal, direction);
    pdf = e.Density * (x - origin).LengthSquared / cosL;
    return true;
  }

  /// <summary>The cone a sphere subtends from <paramref name="x"/>: its axis, the cosine of its half-angle, its solid angle; false from inside or on it.</summary>
  static bool Cone(in Emitter e, in Vector3d x, out Vector3d axis, out double cosMax, out double solidAngle)
  {
    Vector3d toCentre = e.Corner - x;
    double d2 = toCentre.LengthSquared;
    double r2 = e.Radius * e.Radius;
    if (!(d2 > r2 * (1.0 + OnSphere)))
    {
      axis = default;
      cosMax = solidAngle = 0.0;
      return false;
    }
    axis = toCentre / Math.Sqrt(d2);
    double sin2 = r2 / d2;
    cosMax = Math.Sqrt(1.0 - sin2);
    solidAngle = 2.0 * Math.PI * sin2 / (1.0 + cosMax);   // 2π(1 − cos θmax) without cancellation for small spheres
    return true;
  }

  /// <summary>The emitters of the scene under <paramref name="root"/>, in their current placement.</summary>
  public static EmitterSet Of(IIntersectable? root)
  {
    var found = new List<(ISolid, Emitter)>();
    if (root is ISceneNode node)
      Collect(node, found);
    return found.Count == 0 ? Empty : new EmitterSet(found);
  }

  static void Collect(ISceneNode node, List<(ISolid, Emitter)> found)
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
        found.Add((plane, new Emitter(a, b - a, c - a, normal, 0.0, radiance, 0.0)));
    }
    else if (node is Sphere sphere && SubclassCheck.KeepsGeometry(sphere, typeof(Sphere)) && EmissionOf(sphere) is Rgb glow &&
             Similarity(sphere.ToWorld(), out double scale))
    {
      Vector3d centre = Vector3d.TransformPosition(Vector3d.Zero, sphere.ToWorld());
      found.Add((sphere, new Emitter(centre, Vector3d.Zero, Vector3d.Zero, Vector3d.Zero, scale, glow, 0.0)));
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
