using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Uniform Catmull–Rom interpolation between the middle two of four knots: the curve passes
/// through every knot, and its tangent at a knot is half the difference of the neighbours.
/// Linear types use the cubic weights; quaternions use the same construction with slerp in
/// place of lerp (the Barry–Goldman pyramid), which stays on the unit sphere.
/// </summary>
public static class CatmullRom
{
  /// <summary>Weights of knots p0..p3 at fraction <paramref name="f"/> ∈ [0, 1] of the p1 → p2 segment.</summary>
  public static void Weights(double f, out double w0, out double w1, out double w2, out double w3)
  {
    double f2 = f * f, f3 = f2 * f;
    w0 = 0.5 * (-f + 2.0 * f2 - f3);
    w1 = 0.5 * (2.0 - 5.0 * f2 + 3.0 * f3);
    w2 = 0.5 * (f + 4.0 * f2 - 3.0 * f3);
    w3 = 0.5 * (f3 - f2);
  }

  /// <summary>
  /// The curve point at fraction <paramref name="f"/> of the segment from <paramref name="p1"/> to <paramref name="p2"/>;
  /// <paramref name="f"/> ≤ 0 gives exactly p1, <paramref name="f"/> ≥ 1 exactly p2. The other overloads do the same for their types.
  /// </summary>
  /// <param name="p0">The knot before the segment.</param>
  /// <param name="p1">The segment's first knot.</param>
  /// <param name="p2">The segment's second knot.</param>
  /// <param name="p3">The knot after the segment.</param>
  /// <param name="f">Fraction of the segment, 0 to 1.</param>
  public static double Interpolate(double p0, double p1, double p2, double p3, double f)
  {
    // The end points are returned exactly, not up to rounding.
    if (f <= 0.0)
      return p1;
    if (f >= 1.0)
      return p2;
    Weights(f, out double w0, out double w1, out double w2, out double w3);
    return w0 * p0 + w1 * p1 + w2 * p2 + w3 * p3;
  }

  /// <inheritdoc cref="Interpolate(double, double, double, double, double)"/>
  public static float Interpolate(float p0, float p1, float p2, float p3, double f) =>
    (float)Interpolate((double)p0, p1, p2, p3, f);

  /// <inheritdoc cref="Interpolate(double, double, double, double, double)"/>
  public static Vector3d Interpolate(Vector3d p0, Vector3d p1, Vector3d p2, Vector3d p3, double f)
  {
    if (f <= 0.0)
      return p1;
    if (f >= 1.0)
      return p2;
    Weights(f, out double w0, out double w1, out double w2, out double w3);
    return w0 * p0 + w1 * p1 + w2 * p2 + w3 * p3;
  }

  /// <inheritdoc cref="Interpolate(double, double, double, double, double)"/>
  public static Vector4d Interpolate(Vector4d p0, Vector4d p1, Vector4d p2, Vector4d p3, double f)
  {
    if (f <= 0.0)
      return p1;
    if (f >= 1.0)
      return p2;
    Weights(f, out double w0, out double w1, out double w2, out double w3);
    return w0 * p0 + w1 * p1 + w2 * p2 + w3 * p3;
  }

  /// <inheritdoc cref="Interpolate(double, double, double, double, double)"/>
  public static Vector3 Interpolate(Vector3 p0, Vector3 p1, Vector3 p2, Vector3 p3, double f) =>
    (Vector3)Interpolate((Vector3d)p0, p1, p2, p3, f);

  /// <inheritdoc cref="Interpolate(double, double, double, double, double)"/>
  public static Vector4 Interpolate(Vector4 p0, Vector4 p1, Vector4 p2, Vector4 p3, double f) =>
    (Vector4)Interpolate((Vector4d)p0, p1, p2, p3, f);

  /// <summary>
  /// Element-wise interpolation of matrices: right for translations and scales, only
  /// approximate for rotations (animate those as quaternions).
  /// </summary>
  public static Matrix4d Interpolate(Matrix4d p0, Matrix4d p1, Matrix4d p2, Matrix4d p3, double f) => new(
    Interpolate(p0.Row0, p1.Row0, p2.Row0, p3.Row0, f),
    Interpolate(p0.Row1, p1.Row1, p2.Row1, p3.Row1, f),
    Interpolate(p0.Row2, p1.Row2, p2.Row2, p3.Row2, f),
    Interpolate(p0.Row3, p1.Row3, p2.Row3, p3.Row3, f));

  /// <summary>
  /// Spherical Catmull–Rom of unit quaternions: the Barry–Goldman pyramid of the uniform
  /// spline with every lerp replaced by slerp. Knots are first moved to one hemisphere
  /// (q and −q are the same rotation) so the curve takes the short way; the result is a unit
  /// quaternion equal to p1 at f = 0 and to p2 at f = 1.
  /// </summary>
  public static Quaterniond Interpolate(Quaterniond p0, Quaterniond p1, Quaterniond p2, Quaterniond p3, double f)
  {
    p1 = Unit(p1);
    p0 = Align(Unit(p0), p1);
    p2 = Align(Unit(p2), p1);
    p3 = Align(Unit(p3), p2);
    if (f <= 0.0)
      return p1;
    if (f >= 1.0)
      return p2;

    // Knots sit at parameters -1, 0, 1, 2; each level blends over the span of its inputs.
    Quaterniond a1 = SlerpAny(p0, p1, f + 1.0);
    Quaterniond a2 = SlerpAny(p1, p2, f);
    Quaterniond a3 = SlerpAny(p2, p3, f - 1.0);
    Quaterniond b1 = SlerpAny(a1, a2, 0.5 * (f + 1.0));
    Quaterniond b2 = SlerpAny(a2, a3, 0.5 * f);
    return Unit(SlerpAny(b1, b2, f));
  }

  /// <summary>
  /// Slerp along the arc from <paramref name="a"/> to <paramref name="b"/> for any t (t outside [0, 1]
  /// extrapolates along the same great circle), without flipping b's sign.
  /// </summary>
  public static Quaterniond SlerpAny(Quaterniond a, Quaterniond b, double t)
  {
    double cos = Math.Clamp(Quaterniond.Dot(a, b), -1.0, 1.0);
    double angle = Math.Acos(cos);
    double wa, wb;
    if (angle < 1.0e-6)
    {
      wa = 1.0 - t;
      wb = t;
    }
    else
    {
      double sin = Math.Sin(angle);
      wa = Math.Sin((1.0 - t) * angle) / sin;
      wb = Math.Sin(t * angle) / sin;
    }
    return new Quaterniond(wa * a.X + wb * b.X, wa * a.Y + wb * b.Y, wa * a.Z + wb * b.Z, wa * a.W + wb * b.W);
  }

  static Quaterniond Unit(Quaterniond q) => q.LengthSquared > 0.0 ? q.Normalized() : Quaterniond.Identity;

  static Quaterniond Align(Quaterniond q, Quaterniond reference) =>
    Quaterniond.Dot(q, reference) < 0.0 ? new Quaterniond(-q.X, -q.Y, -q.Z, -q.W) : q;
}
