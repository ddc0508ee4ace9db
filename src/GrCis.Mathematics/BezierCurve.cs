using System;
using System.Collections.Generic;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's 2D Bézier curve of any degree, given its control points; <see cref="Parallel"/> shifts the evaluated points
/// sideways (to the right of the direction of travel) to trace a parallel curve.
/// </summary>
public struct BezierCurve
{
  readonly List<Vector2> points;

  /// <summary>The sideways offset of the evaluated points; 0 is the curve itself.</summary>
  public float Parallel;

  /// <summary>The control points, in order (the curve's own list).</summary>
  public readonly IList<Vector2> Points => points;

  /// <summary>The curve through a copy of <paramref name="points"/>, with no parallel offset.</summary>
  public BezierCurve(IEnumerable<Vector2> points) : this(0f, points)
  {
  }

  /// <summary>The curve through a copy of <paramref name="points"/>, with no parallel offset.</summary>
  public BezierCurve(params Vector2[] points) : this(0f, (IEnumerable<Vector2>)points)
  {
  }

  /// <summary>The curve through a copy of <paramref name="points"/>, offset sideways by
  /// <paramref name="parallel"/>.</summary>
  public BezierCurve(float parallel, params Vector2[] points) : this(parallel, (IEnumerable<Vector2>)points)
  {
  }

  /// <summary>The curve through a copy of <paramref name="points"/>, offset sideways by <paramref name="parallel"/>;
  /// null points throw <see cref="System.ArgumentNullException"/>.</summary>
  public BezierCurve(float parallel, IEnumerable<Vector2> points)
  {
    ArgumentNullException.ThrowIfNull(points);
    Parallel = parallel;
    this.points = new List<Vector2>(points);
  }

  /// <summary>The point at <paramref name="t"/> (0..1), offset by <see cref="Parallel"/>, as
  /// <see cref="CalculatePoint(IList{Vector2}, float, float)"/>.</summary>
  public readonly Vector2 CalculatePoint(float t) => CalculatePoint(points, t, Parallel);
  /// <summary>The approximate length, offset by <see cref="Parallel"/>, as
  /// <see cref="CalculateLength(IList{Vector2}, float, float)"/>.</summary>
  public readonly float CalculateLength(float precision) => CalculateLength(points, precision, Parallel);

  /// <summary>The point at <paramref name="t"/> (0..1) of the curve with control points <paramref name="points"/>, with
  /// no offset.</summary>
  public static Vector2 CalculatePoint(IList<Vector2> points, float t) => CalculatePoint(points, t, 0f);

  /// <summary>The Bernstein sum at <paramref name="t"/> (0..1), moved <paramref name="parallel"/> to the right of the tangent.</summary>
  public static Vector2 CalculatePoint(IList<Vector2> points, float t, float parallel)
  {
    Vector2 r = Bernstein(points, points.Count - 1, t);
    if (parallel == 0f)
      return r;
    Vector2 direction = t != 0f ? r - Bernstein(points, points.Count - 2, t) : points[1] - points[0];
    return r + direction.Normalized().PerpendicularRight * parallel;
  }

  /// <summary>Σ C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ pᵢ over the first n + 1 points (weights in double, sums in float).</summary>
  static Vector2 Bernstein(IList<Vector2> points, int n, float t)
  {
    Vector2 r = Vector2.Zero;
    double c = 1.0 - t;
    for (int i = 0; i <= n && i < points.Count; i++)
    {
      float w = MathHelper.BinomialCoefficient(n, i) * (float)(Math.Pow(t, i) * Math.Pow(c, n - i));
      r.X += w * points[i].X;
      r.Y += w * points[i].Y;
    }
    return r;
  }

  /// <summary>The approximate length of the curve with control points <paramref name="points"/>, with no offset, as
  /// <see cref="CalculateLength(IList{Vector2}, float, float)"/>.</summary>
  public static float CalculateLength(IList<Vector2> points, float precision) => CalculateLength(points, precision, 0f);

  /// <summary>
  /// The length of the polyline through the points at t = 0, precision, 2·precision, …, up to the first step at or
  /// past 1: when <paramref name="precision"/> does not divide 1, the last point lies beyond the curve's end (t &gt; 1).
  /// </summary>
  public static float CalculateLength(IList<Vector2> points, float precision, float parallel)
  {
    float length = 0f;
    Vector2 old = CalculatePoint(points, 0f, parallel);
    for (float i = precision; i < 1f + precision; i += precision)
    {
      Vector2 next = CalculatePoint(points, i, parallel);
      length += (next - old).Length;
      old = next;
    }
    return length;
  }
}
