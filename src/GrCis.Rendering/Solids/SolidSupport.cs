using System;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>Numerics and completion helpers shared by the elementary solids.</summary>
internal static class SolidSupport
{
  /// <summary>Stand-in for infinite extents in bounding boxes.</summary>
  public const double INFINITY_PLACEHOLDER = 1.0e6;

  /// <summary>
  /// Real roots of <c>a t² + 2 halfB t + c = 0</c> with the cancellation-free formula
  /// (<c>q = -(halfB ± √disc)</c>, <c>t = q/a</c>, <c>t = c/q</c>); <paramref name="disc"/> is the
  /// caller's (preferably accurately computed) <c>halfB² − a c</c>. False when there is no
  /// pair of distinct roots.
  /// </summary>
  public static bool SolveQuadratic(double a, double halfB, double c, double disc, out double t0, out double t1)
  {
    t0 = t1 = 0.0;
    if (!(disc > 0.0) || a == 0.0)
      return false;
    double q = -(halfB + Math.CopySign(Math.Sqrt(disc), halfB));
    t0 = q / a;
    t1 = q != 0.0 ? c / q : -t0;
    if (t0 > t1)
      (t0, t1) = (t1, t0);
    return true;
  }

  /// <summary>Replaces an infinite bound by ±<see cref="INFINITY_PLACEHOLDER"/>.</summary>
  public static double Finite(double x) =>
    double.IsInfinity(x) ? Math.CopySign(INFINITY_PLACEHOLDER, x) : x;

  /// <summary>
  /// Sets the world normal (cofactor transform of the local one, correct under non-uniform
  /// scale) and the world tangents. Requires <see cref="Intersection.LocalToWorld"/> and
  /// <see cref="Intersection.WorldToLocal"/>.
  /// </summary>
  public static void SetWorldFrame(Intersection inter, Vector3d normalLocal, Vector3d tangentU, Vector3d tangentV)
  {
    inter.NormalLocal = normalLocal;
    inter.Normal = Vector3d.TransformNormalInverse(normalLocal, inter.WorldToLocal);
    inter.TangentU = SafeNormalized(Vector3d.TransformVector(tangentU, inter.LocalToWorld));
    inter.TangentV = SafeNormalized(Vector3d.TransformVector(tangentV, inter.LocalToWorld));
  }

  /// <summary>World frame from the local normal alone (tangents: any perpendicular pair).</summary>
  public static void SetWorldFrame(Intersection inter, Vector3d normalLocal)
  {
    Vector3d n = normalLocal.LengthSquared > 0.0 ? normalLocal : Vector3d.UnitZ;
    MathSupport.Geometry.GetTangents(n, out Vector3d u, out Vector3d v);
    SetWorldFrame(inter, normalLocal, u, v);
  }

  public static Vector3d SafeNormalized(Vector3d v)
  {
    double l2 = v.LengthSquared;
    return l2 > 0.0 ? v / Math.Sqrt(l2) : v;
  }

  /// <summary>Longitude texture coordinate about the z axis: atan2(y, x)/2π + 0.5 (0 on the axis).</summary>
  public static double Longitude(double x, double y) =>
    x == 0.0 && y == 0.0 ? 0.0 : Math.Atan2(y, x) / (2.0 * Math.PI) + 0.5;

  // ---------------------------------------------------------------- fast path (IRecordSolid) support

  /// <summary>The test <see cref="Intersection.FirstIntersection"/> applies (with the world ray's |p1|²).</summary>
  public static bool Accepted(double t, double len2) => t > 0.0 && t * t * len2 > Intersection.RAY_EPSILON2;

  /// <summary>
  /// First accepted record of a one-sided "front" solid's list: the front hit at <paramref name="t"/>
  /// (an entry), else — with a <paramref name="shell"/> — the exit <see cref="Intersection.SHELL_THICKNESS"/>
  /// behind it. <see cref="SolidRecord.Aux"/> keeps the ray direction for texture coordinates.
  /// </summary>
  public static bool FrontOrShell(double t, in Vector3d p0, in Vector3d p1, double len2, bool shell, out SolidRecord hit, out bool insideBefore)
  {
    hit = default;
    insideBefore = false;
    if (Accepted(t, len2))
    {
      hit = new SolidRecord { T = t, CoordLocal = p0 + t * p1, Aux = p1, Enter = true, Front = true };
      return true;
    }
    if (!shell)
    {
      insideBefore = true;
      return false;
    }
    double t2 = t + Intersection.SHELL_THICKNESS;
    if (!Accepted(t2, len2))
      return false;
    insideBefore = true;
    hit = new SolidRecord { T = t2, CoordLocal = p0 + t2 * p1, Aux = p1 };
    return true;
  }

  /// <summary>
  /// The whole list of a one-sided "front" solid hit at <paramref name="t"/> (see <see cref="FrontOrShell"/>):
  /// the front entry, and with a <paramref name="shell"/> the exit behind it. Returns the count.
  /// </summary>
  public static int FrontAndShell(double t, in Vector3d p0, in Vector3d p1, bool shell, Span<SolidRecord> dst)
  {
    dst[0] = new SolidRecord { T = t, CoordLocal = p0 + t * p1, Aux = p1, Enter = true, Front = true };
    if (!shell)
      return 1;
    double t2 = t + Intersection.SHELL_THICKNESS;
    dst[1] = new SolidRecord { T = t2, CoordLocal = p0 + t2 * p1, Aux = p1 };
    return 2;
  }

  /// <summary>
  /// First accepted record of the list [enter at <paramref name="t0"/>, exit at <paramref name="t1"/>]:
  /// <paramref name="second"/> tells which; <paramref name="insideBefore"/> is the CSG state before it.
  /// </summary>
  public static bool FirstOfPair(double t0, double t1, double len2, out bool second, out bool insideBefore)
  {
    second = insideBefore = false;
    if (Accepted(t0, len2))
      return true;
    if (Accepted(t1, len2))
    {
      second = insideBefore = true;
      return true;
    }
    return false;
  }
}
