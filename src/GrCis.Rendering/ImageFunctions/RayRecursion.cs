using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// What a <see cref="RecursionFunction"/> asks the tracer to do: add a direct colour and trace further
/// rays. <see cref="Recursion"/> is the default way of doing it; a subclass may override it.
/// </summary>
public class RayRecursion
{
  /// <summary>One more ray to trace, with the coefficient its colour is multiplied by.</summary>
  public struct RayContribution
  {
    /// <summary>Origin of the ray in world coordinates.</summary>
    public Vector3d origin;
    /// <summary>Direction of the ray in world coordinates.</summary>
    public Vector3d direction;
    /// <summary>What the ray's colour is multiplied by: one value per band, one value for every band, or null for 1.</summary>
    public double[]? coefficient;
    /// <summary>Importance of the ray, handed to the tracer's shading: the rays it spawns in turn are traced while their importance stays at or above <see cref="RayTracing.MinImportance"/>.</summary>
    public double importance;

    /// <summary>A ray from <paramref name="p0"/> (moved by <see cref="Intersection.RAY_EPSILON"/> along the ray, off the surface).</summary>
    public RayContribution(in Vector3d p0, in Vector3d p1, in double[]? coeff = null, in double imp = 1.0)
    {
      origin = p0 + Intersection.RAY_EPSILON * p1;
      direction = p1;
      coefficient = coeff;
      importance = imp;
    }

    /// <summary>Argument order of earlier versions: importance before the coefficient.</summary>
    public RayContribution(Vector3d p0, Vector3d p1, double importance, double[]? coefficient = null)
      : this(p0, p1, coefficient, importance)
    {
    }

    /// <summary>A ray from the intersection point in direction <paramref name="dir"/>.</summary>
    public RayContribution(in Intersection i, in Vector3d dir, in double imp)
    {
      origin = i.CoordWorld + Intersection.RAY_EPSILON * dir;
      direction = dir;
      coefficient = null;
      importance = imp;
    }

    /// <summary>A copy of <paramref name="r"/> (the coefficient array is shared).</summary>
    /// <param name="r">The ray to copy.</param>
    public RayContribution(RayContribution r)
    {
      origin = r.origin;
      direction = r.direction;
      coefficient = r.coefficient;
      importance = r.importance;
    }

    /// <summary>Earlier name of <see cref="origin"/>.</summary>
    public Vector3d p0
    {
      readonly get => origin;
      set => origin = value;
    }

    /// <summary>Earlier name of <see cref="direction"/>.</summary>
    public Vector3d p1
    {
      readonly get => direction;
      set => direction = value;
    }
  }

  /// <summary>Colour added directly (null = nothing; one value = the same for every band).</summary>
  public double[]? DirectContribution;

  /// <summary>Further rays (null or empty = none).</summary>
  public List<RayContribution>? Rays;

  /// <summary>Nothing to add and no rays; fill <see cref="DirectContribution"/> and <see cref="Rays"/> afterwards.</summary>
  public RayRecursion() { }

  /// <summary>A direct colour and at most one further ray.</summary>
  /// <param name="direct">Colour added directly (<see cref="DirectContribution"/>), or null.</param>
  /// <param name="ray">A ray to trace, or null.</param>
  public RayRecursion(in double[]? direct, in RayContribution? ray = null)
  {
    DirectContribution = direct;
    Rays = new List<RayContribution>();
    if (ray != null)
      Rays.Add(ray.Value);
  }

  /// <summary>A direct colour and up to two further rays (e.g. a reflected and a refracted one).</summary>
  /// <param name="direct">Colour added directly (<see cref="DirectContribution"/>), or null.</param>
  /// <param name="ray1">A ray to trace, or null.</param>
  /// <param name="ray2">Another ray to trace, or null.</param>
  public RayRecursion(double[]? direct, RayContribution? ray1, RayContribution? ray2) : this(direct, ray1)
  {
    if (ray2 != null)
      Rays!.Add(ray2.Value);
  }

  /// <summary>A direct colour and a list of further rays.</summary>
  /// <param name="direct">Colour added directly (<see cref="DirectContribution"/>), or null.</param>
  /// <param name="rays">The rays to trace (<see cref="Rays"/>; the list is kept, not copied), or null.</param>
  public RayRecursion(in double[]? direct, in List<RayContribution>? rays)
  {
    DirectContribution = direct;
    Rays = rays;
  }

  /// <summary>Hash multiplier of each further ray's result.</summary>
  protected const long HASH_RAY = 113L;

  /// <summary>
  /// The default behaviour: adds <see cref="DirectContribution"/>, then (below the tracer's MaxLevel)
  /// traces every ray one level deeper and adds its colour times its coefficient. Returns the hash.
  /// </summary>
  public virtual long Recursion(RayTracing rt, Intersection i, long hash, int depth, double[] color)
  {
    if (DirectContribution is { Length: > 0 } direct)
    {
      if (direct.Length == 1)
        for (int b = 0; b < color.Length; b++)
          color[b] += direct[0];
      else
        AddScaled(direct, 1.0, color);
    }

    if (Rays == null || Rays.Count == 0 || depth++ >= rt.MaxLevel)
      return hash;

    double[] comp = new double[color.Length];
    foreach (RayContribution ray in Rays)
    {
      RayContribution rc = ray;
      hash += HASH_RAY * rt.shade(depth, rc.importance, ref rc.origin, ref rc.direction, comp);
      if (ray.coefficient == null)
        AddScaled(comp, 1.0, color);
      else if (ray.coefficient.Length == 1)
        AddScaled(comp, ray.coefficient[0], color);
      else
        AddWeighted(comp, ray.coefficient, color);
    }
    return hash;
  }

  /// <summary>dst += mul * src over the bands both have (GrCis's Util.ColorAdd).</summary>
  static void AddScaled(double[] src, double mul, double[] dst)
  {
    int n = Math.Min(src.Length, dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] += mul * src[i];
  }

  /// <summary>dst += weight * src per band, over the bands all three have.</summary>
  static void AddWeighted(double[] src, double[] weight, double[] dst)
  {
    int n = Math.Min(Math.Min(src.Length, weight.Length), dst.Length);
    for (int i = 0; i < n; i++)
      dst[i] += weight[i] * src[i];
  }
}
