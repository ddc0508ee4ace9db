using System;
using OpenTK.Mathematics;

namespace GrCis.Bench.Embree;

/// <summary>
/// Rays both libraries trace: every coordinate is a float (what Embree takes), held as doubles for the
/// library, so the two see the same numbers. A ray is <c>o + t d</c> for t in [TNear, TFar].
/// </summary>
internal sealed class RaySet
{
  public readonly string Name;
  public readonly double[] Ox, Oy, Oz, Dx, Dy, Dz, TNear, TFar;

  /// <summary>True for segments (occlusion queries), false for closest-hit rays.</summary>
  public readonly bool Segments;

  public int Count => Ox.Length;

  RaySet(string name, int n, bool segments)
  {
    Name = name;
    Segments = segments;
    Ox = new double[n]; Oy = new double[n]; Oz = new double[n];
    Dx = new double[n]; Dy = new double[n]; Dz = new double[n];
    TNear = new double[n]; TFar = new double[n];
  }

  void Set(int i, Vector3d o, Vector3d d, double tFar)
  {
    Ox[i] = (float)o.X; Oy[i] = (float)o.Y; Oz[i] = (float)o.Z;
    Dx[i] = (float)d.X; Dy[i] = (float)d.Y; Dz[i] = (float)d.Z;
    // The library accepts hits with t·|d| > RAY_EPSILON (Intersection.FirstIntersection): Embree is told the same.
    double length = Math.Sqrt(Dx[i] * Dx[i] + Dy[i] * Dy[i] + Dz[i] * Dz[i]);
    TNear[i] = Rendering.Intersection.RAY_EPSILON / length;
    // A shadow segment ends at 1 (+ RAY_EPSILON/|d|, PreparedScene.Occluded's "not far").
    TFar[i] = tFar + (double.IsFinite(tFar) ? Rendering.Intersection.RAY_EPSILON / length : 0.0);
  }

  /// <summary>
  /// A pinhole camera looking at the box's centre from the direction of <c>grcis bench</c>'s mesh scene camera,
  /// as far away as a 25 degree field of view needs to hold the box's bounding sphere; <paramref name="size"/>²
  /// rays ordered in 4×4 pixel tiles (so 16 consecutive rays form a coherent packet).
  /// </summary>
  public static RaySet CameraTight(Vector3d min, Vector3d max, int size)
  {
    const double fieldOfView = 25.0;
    Vector3d center = 0.5 * (min + max);
    double radius = 0.5 * (max - min).Length;
    double half = MathHelper.DegreesToRadians(0.5 * fieldOfView);
    Vector3d forward = new Vector3d(-0.12, -0.3, 1.0).Normalized();
    Vector3d right = Vector3d.Cross(Vector3d.UnitY, forward).Normalized();
    Vector3d up = Vector3d.Cross(forward, right);
    Vector3d eye = center - forward * (radius / Math.Sin(half));
    double span = Math.Tan(half);

    int tiles = (size + 3) / 4;
    var set = new RaySet("camera, tight (25 degrees)", size * size, false);
    int i = 0;
    for (int ty = 0; ty < tiles; ty++)
      for (int tx = 0; tx < tiles; tx++)
        for (int y = 4 * ty; y < Math.Min(size, 4 * ty + 4); y++)
          for (int x = 4 * tx; x < Math.Min(size, 4 * tx + 4); x++)
          {
            double sx = (2.0 * (x + 0.5) / size - 1.0) * span, sy = (1.0 - 2.0 * (y + 0.5) / size) * span;
            set.Set(i++, eye, (forward + sx * right + sy * up).Normalized(), double.PositiveInfinity);
          }
    return set;
  }

  /// <summary>Origins uniform in the box, directions uniform on the sphere (seeded).</summary>
  public static RaySet Incoherent(Vector3d min, Vector3d max, int count, int seed)
  {
    var random = new Random(seed);
    var set = new RaySet("incoherent, closest hit", count, false);
    for (int i = 0; i < count; i++)
    {
      double z = 2.0 * random.NextDouble() - 1.0, phi = 2.0 * Math.PI * random.NextDouble();
      double r = Math.Sqrt(Math.Max(0.0, 1.0 - z * z));
      set.Set(i, Inside(random, min, max), new Vector3d(r * Math.Cos(phi), r * Math.Sin(phi), z), double.PositiveInfinity);
    }
    return set;
  }

  /// <summary>Segments between two points uniform in the box (seeded): <c>d = b − a</c>, t in (0, 1].</summary>
  public static RaySet SegmentsBetween(Vector3d min, Vector3d max, int count, int seed)
  {
    var random = new Random(seed);
    var set = new RaySet("incoherent, occlusion on segments", count, true);
    for (int i = 0; i < count; i++)
    {
      Vector3d a = Rounded(Inside(random, min, max)), b = Rounded(Inside(random, min, max));
      set.Set(i, a, b - a, 1.0);
    }
    return set;
  }

  /// <summary>
  /// Shadow rays as a renderer sends them: from the surface points where <paramref name="firstHit"/> finds the incoherent
  /// rays of <paramref name="from"/> hitting, to a random point of a sphere of radius <paramref name="lightRadius"/> around
  /// <paramref name="center"/> (a light outside the mesh, seeded); segments, t in (0, 1].
  /// </summary>
  public static RaySet ShadowFromSurfaces(RaySet from, Func<Vector3d, Vector3d, double> firstHit, Vector3d center, double lightRadius, int seed)
  {
    var random = new Random(seed);
    var starts = new System.Collections.Generic.List<Vector3d>();
    for (int i = 0; i < from.Count; i++)
    {
      var p0 = new Vector3d(from.Ox[i], from.Oy[i], from.Oz[i]);
      var p1 = new Vector3d(from.Dx[i], from.Dy[i], from.Dz[i]);
      double t = firstHit(p0, p1);
      if (double.IsFinite(t))
        starts.Add(Rounded(p0 + t * p1));
    }
    var set = new RaySet("shadow rays from surface points to a light", starts.Count, true);
    for (int i = 0; i < starts.Count; i++)
    {
      double z = 2.0 * random.NextDouble() - 1.0, phi = 2.0 * Math.PI * random.NextDouble();
      double r = Math.Sqrt(Math.Max(0.0, 1.0 - z * z));
      Vector3d light = Rounded(center + lightRadius * new Vector3d(r * Math.Cos(phi), r * Math.Sin(phi), z));
      set.Set(i, starts[i], light - starts[i], 1.0);
    }
    return set;
  }

  static Vector3d Inside(Random random, Vector3d min, Vector3d max) =>
    new(min.X + random.NextDouble() * (max.X - min.X), min.Y + random.NextDouble() * (max.Y - min.Y), min.Z + random.NextDouble() * (max.Z - min.Z));

  static Vector3d Rounded(Vector3d v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
