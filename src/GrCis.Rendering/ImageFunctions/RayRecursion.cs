using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>What a <see cref="RecursionFunction"/> asks the tracer to do: add a direct colour and trace further rays.</summary>
public class RayRecursion
{
  /// <summary>One more ray to trace from the intersection, with the coefficient its colour is multiplied by.</summary>
  public class RayContribution
  {
    public Vector3d p0;
    public Vector3d p1;
    public double importance;
    public double[]? coefficient;
    public int size;

    /// <summary>A ray from the intersection point in direction <paramref name="dir"/>.</summary>
    public RayContribution(Intersection i, Vector3d dir, double importance)
    {
      p0 = i.CoordWorld;
      p1 = dir;
      this.importance = importance;
    }

    public RayContribution(Vector3d p0, Vector3d p1, double importance, double[]? coefficient = null)
    {
      this.p0 = p0;
      this.p1 = p1;
      this.importance = importance;
      this.coefficient = coefficient;
    }
  }

  /// <summary>Colour added directly (null = nothing).</summary>
  public double[]? DirectContribution;

  /// <summary>Further rays (null or empty = none).</summary>
  public List<RayContribution>? Rays;

  public RayRecursion() { }

  public RayRecursion(double[]? direct, RayContribution? ray = null)
  {
    DirectContribution = direct;
    if (ray != null)
      Rays = new List<RayContribution> { ray };
  }

  public RayRecursion(double[]? direct, RayContribution? ray1, RayContribution? ray2) : this(direct, ray1)
  {
    if (ray2 != null)
      (Rays ??= new List<RayContribution>()).Add(ray2);
  }
}
