using System;
using System.Collections.Generic;
using System.Globalization;
using OpenTK.Mathematics;

namespace MathSupport;

/// <summary>GrCis's geometry helpers for sampling, slab tests and parsing vectors from parameters.</summary>
public static partial class Geometry
{
  /// <summary>
  /// A unit direction around +z: tilted from z by a normally distributed angle (σ = <paramref name="variance"/>,
  /// radians) towards a uniformly random azimuth in [0, π) (the tilt's sign covers the other half).
  /// </summary>
  public static Vector3d RandomDirectionNormal(RandomJames rnd, double variance) => new(Tilt(rnd, variance).Row2);

  /// <summary><see cref="RandomDirectionNormal(RandomJames, double)"/> around <paramref name="dir"/> instead of +z.</summary>
  public static Vector3d RandomDirectionNormal(RandomJames rnd, Vector3d dir, double variance)
  {
    dir.Normalize();
    GetTangents(ref dir, out Vector3d u, out Vector3d v);
    // Rows: the frame that takes +z to dir.
    var frame = new Matrix4d(new Vector4d(u.Normalized(), 0.0), new Vector4d(v.Normalized(), 0.0), new Vector4d(dir, 0.0), Vector4d.UnitW);
    return new Vector3d((Tilt(rnd, variance) * frame).Row2);
  }

  /// <summary>A random tilt of +z: about x by a normal deviation, then about z by a uniform orientation (row vectors).</summary>
  static Matrix4d Tilt(RandomJames rnd, double variance)
  {
    double deviation = rnd.Normal(0.0, variance);
    double orientation = rnd.RandomDouble(0.0, Math.PI);
    return Matrix4d.CreateRotationX(deviation) * Matrix4d.CreateRotationZ(orientation);
  }

  /// <summary>
  /// Ray <c>p0 + t p1</c> against the box [<paramref name="ul"/>, <paramref name="ul"/> + <paramref name="size"/>]
  /// (slabs): true and (t entry, t exit) in <paramref name="result"/>, or false and (−1, −1).
  /// </summary>
  public static bool RayBoxIntersection(ref Vector3d p0, ref Vector3d p1, ref Vector3d ul, ref Vector3d size, out Vector2d result)
  {
    var inv = new Vector3d(IsZero(p1.X) ? double.PositiveInfinity : 1.0 / p1.X,
                           IsZero(p1.Y) ? double.PositiveInfinity : 1.0 / p1.Y,
                           IsZero(p1.Z) ? double.PositiveInfinity : 1.0 / p1.Z);
    return RayBoxIntersectionInv(ref p0, ref inv, ref ul, ref size, out result);
  }

  /// <summary><see cref="RayBoxIntersection"/> with the ray's inverted direction (infinite for a zero component).</summary>
  public static bool RayBoxIntersectionInv(ref Vector3d p0, ref Vector3d p1inv, ref Vector3d ul, ref Vector3d size, out Vector2d result)
  {
    result = new Vector2d(-1.0, -1.0);
    double tMin = double.NegativeInfinity, tMax = double.PositiveInfinity;
    for (int axis = 0; axis < 3; axis++)
    {
      double o = p0[axis], inv = p1inv[axis], lo = ul[axis], extent = size[axis];
      if (double.IsInfinity(inv))
      {
        // Parallel to the slab: inside it or never.
        if (o <= lo || o >= lo + extent)
          return false;
        continue;
      }
      double t1 = (lo - o) * inv, t2 = t1 + extent * inv;
      if (inv < 0.0)
        (t1, t2) = (t2, t1);
      tMin = Math.Max(tMin, t1);
      tMax = Math.Min(tMax, t2);
      if (tMin > tMax)
        return false;
    }
    result = new Vector2d(tMin, tMax);
    return true;
  }

  /// <summary><see cref="RayBoxIntersectionInv(ref Vector3d, ref Vector3d, ref Vector3d, ref Vector3d, out Vector2d)"/> for a single-precision box.</summary>
  public static bool RayBoxIntersectionInv(ref Vector3d p0, ref Vector3d p1inv, ref Vector3 ul, ref Vector3 size, out Vector2d result)
  {
    Vector3d u = ul, s = size;
    return RayBoxIntersectionInv(ref p0, ref p1inv, ref u, ref s, out result);
  }

  /// <summary>
  /// Numbers of a vector written as text: optional ( ) or [ ] around, separated by ';', else ':', else ','
  /// (invariant culture); an empty item is 0, an unreadable one is skipped. Null for null or blank text.
  /// </summary>
  public static double[]? TryParseDoubleVector(string? str)
  {
    string[]? items = VectorItems(str);
    if (items == null)
      return null;
    var values = new List<double>(items.Length);
    foreach (string item in items)
      if (item.Trim().Length == 0)
        values.Add(0.0);
      else if (double.TryParse(item, NumberStyles.Number, CultureInfo.InvariantCulture, out double v))
        values.Add(v);
    return values.ToArray();
  }

  /// <summary>Single-precision <see cref="TryParseDoubleVector"/>.</summary>
  public static float[]? TryParseFloatVector(string? str)
  {
    double[]? d = TryParseDoubleVector(str);
    return d == null ? null : Array.ConvertAll(d, x => (float)x);
  }

  static string[]? VectorItems(string? str)
  {
    if (str == null || (str = str.Trim()).Length == 0)
      return null;
    if ((str[0] == '(' && str[^1] == ')') || (str[0] == '[' && str[^1] == ']'))
      str = str[1..^1];
    char separator = str.Contains(';') ? ';' : str.Contains(':') ? ':' : ',';
    return str.Split(separator);
  }

  /// <summary>A vector from the parsed <c>param</c> text; false (and <paramref name="val"/> kept) when missing or short.</summary>
  public static bool TryParse(Dictionary<string, string> rec, string key, ref Vector3 val)
  {
    if (Read(rec, key, 3) is not double[] v)
      return false;
    val = new Vector3((float)v[0], (float)v[1], (float)v[2]);
    return true;
  }

  /// <summary>A vector from the parsed <c>param</c> text; false (and <paramref name="val"/> kept) when missing or short.</summary>
  public static bool TryParse(Dictionary<string, string> rec, string key, ref Vector2 val)
  {
    if (Read(rec, key, 2) is not double[] v)
      return false;
    val = new Vector2((float)v[0], (float)v[1]);
    return true;
  }

  /// <summary>A vector from the parsed <c>param</c> text; false (and <paramref name="val"/> kept) when missing or short.</summary>
  public static bool TryParse(Dictionary<string, string> rec, string key, ref Vector2d val)
  {
    if (Read(rec, key, 2) is not double[] v)
      return false;
    val = new Vector2d(v[0], v[1]);
    return true;
  }

  /// <summary>A vector from the script context (a vector value, or text).</summary>
  public static bool TryParse(Dictionary<string, object> rec, string key, ref Vector3 val)
  {
    if (Read(rec, key, 3) is not double[] v)
      return false;
    val = new Vector3((float)v[0], (float)v[1], (float)v[2]);
    return true;
  }

  /// <summary>A vector from the script context (a vector value, or text).</summary>
  public static bool TryParse(Dictionary<string, object> rec, string key, ref Vector4 val)
  {
    if (Read(rec, key, 4) is not double[] v)
      return false;
    val = new Vector4((float)v[0], (float)v[1], (float)v[2], (float)v[3]);
    return true;
  }

  /// <summary>The context value as numbers: a 3- or 4-component vector (float or double) or vector text; null when missing or short.</summary>
  static double[]? Read(Dictionary<string, object> rec, string key, int count)
  {
    if (rec == null || !rec.TryGetValue(key, out object? o))
      return null;
    double[]? v = o switch
    {
      Vector3 f when count == 3 => new double[] { f.X, f.Y, f.Z },
      Vector3d d when count == 3 => new[] { d.X, d.Y, d.Z },
      Vector4 f when count == 4 => new double[] { f.X, f.Y, f.Z, f.W },
      Vector4d d when count == 4 => new[] { d.X, d.Y, d.Z, d.W },
      string text => TryParseDoubleVector(text),
      _ => null,
    };
    return v != null && v.Length >= count ? v : null;
  }

  static double[]? Read(Dictionary<string, string> rec, string key, int count)
  {
    if (rec == null || !rec.TryGetValue(key, out string? text))
      return null;
    double[]? v = TryParseDoubleVector(text);
    return v != null && v.Length >= count ? v : null;
  }
}
