using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// A world-space test that lets an open <see cref="Plane"/> member skip its transform chain for rays that leave it:
/// the member keeps its local z as an affine function of the world point (<see cref="PreparedMember.PlaneZ"/>, composed
/// from the chain) with a bound on the magnitudes the chain's rounding can reach (<see cref="PreparedMember.PlaneZAbs"/>).
/// When the ray's local direction is surely upwards (z &gt; 0) and its origin surely above the plane, or below it by
/// less than half of <see cref="Intersection.RAY_EPSILON"/> along the ray, the plane's kernel would find no accepted
/// record and no inside state (t ≤ 0, or too close to count; the record would be an exit from above): the answer of
/// testing it exactly, so skipping it changes nothing.
/// </summary>
internal static class PlaneCull
{
  // Relative slack on the estimate (the chain's and the estimate's rounding are a few ulps per step), and an absolute
  // one for results near the underflow range.
  const double Slack = 1.0e-9, Tiny = 1.0e-300;

  /// <summary>Composes the local z row of a plane member from its chain (world to local, applied first to last).</summary>
  public static void Build(ref PreparedMember m, List<Matrix4d> path)
  {
    // Local z = c · v + off for the point v entering matrix k, walked from the last matrix back to the first;
    // the same with every entry's absolute value bounds the terms the chain's arithmetic meets.
    double cx = 0.0, cy = 0.0, cz = 1.0, off = 0.0;
    double ax = 0.0, ay = 0.0, az = 1.0, aoff = 0.0;
    for (int k = path.Count - 1; k >= 0; k--)
    {
      Matrix4d t = path[k];
      off += t.Row3.X * cx + t.Row3.Y * cy + t.Row3.Z * cz;
      aoff += Math.Abs(t.Row3.X) * ax + Math.Abs(t.Row3.Y) * ay + Math.Abs(t.Row3.Z) * az;
      double nx = t.Row0.X * cx + t.Row0.Y * cy + t.Row0.Z * cz;
      double ny = t.Row1.X * cx + t.Row1.Y * cy + t.Row1.Z * cz;
      double nz = t.Row2.X * cx + t.Row2.Y * cy + t.Row2.Z * cz;
      double bx = Math.Abs(t.Row0.X) * ax + Math.Abs(t.Row0.Y) * ay + Math.Abs(t.Row0.Z) * az;
      double by = Math.Abs(t.Row1.X) * ax + Math.Abs(t.Row1.Y) * ay + Math.Abs(t.Row1.Z) * az;
      double bz = Math.Abs(t.Row2.X) * ax + Math.Abs(t.Row2.Y) * ay + Math.Abs(t.Row2.Z) * az;
      (cx, cy, cz, ax, ay, az) = (nx, ny, nz, bx, by, bz);
    }
    if (!double.IsFinite(cx + cy + cz + off + ax + ay + az + aoff))
      return;
    m.PlaneZ = new Vector4d(cx, cy, cz, off);
    m.PlaneZAbs = new Vector4d(ax, ay, az, aoff);
    m.HasPlaneZ = true;
  }

  /// <summary>
  /// True when the plane member surely has neither an accepted record nor an inside state for the ray
  /// <c>p0 + t p1</c> (|p1|² = <paramref name="len2"/>); false when unsure.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Leaves(in PreparedMember m, in Vector3d p0, in Vector3d p1, double len2)
  {
    Vector4d z = m.PlaneZ, a = m.PlaneZAbs;
    double dz = z.X * p1.X + z.Y * p1.Y + z.Z * p1.Z;
    double low = dz - (Slack * (a.X * Math.Abs(p1.X) + a.Y * Math.Abs(p1.Y) + a.Z * Math.Abs(p1.Z)) + Tiny);
    if (!(low > 0.0))
      return false;
    double oz = z.X * p0.X + z.Y * p0.Y + z.Z * p0.Z + z.W;
    double o = oz - (Slack * (a.X * Math.Abs(p0.X) + a.Y * Math.Abs(p0.Y) + a.Z * Math.Abs(p0.Z) + a.W) + Tiny);
    if (o >= 0.0)
      return true;
    // Below the plane by less than half the epsilon along the ray: t·|p1| < RAY_EPSILON / 2, not accepted.
    double limit = 0.5 * Intersection.RAY_EPSILON * low;
    return o * o * len2 < limit * limit;
  }
}
