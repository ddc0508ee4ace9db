using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Tessellation;
using Xunit.Abstractions;

namespace GrCis.Rendering.Tests.Tessellation;

/// <summary>
/// The tessellation is where the renderer's solids are: rays from the scene's camera through a grid of pixels hit the
/// triangles of the same scene node the renderer's <see cref="ISceneQuery.FirstHit"/> hits. Counted are the pixels where
/// the renderer hits a solid and its four neighbours hit the same one (a silhouette pixel may differ: the polygons lie
/// inside a curved surface by up to their tolerance), and whose hit lies within the tessellated scene's box (an infinite
/// plane is a finite patch; beyond it, towards the horizon, only the renderer has it). At least 98 % of those must hit
/// the same node in the tessellation, and a pixel one misses and the other hits counts against it.
/// </summary>
public class TessellationHitTests(ITestOutputHelper output)
{
  const int Width = 128, Height = 96;
  const double Required = 0.98;

  /// <summary>Built-in scenes whose CSG is unions only (an operand of a difference shows its own surface, not the result's).</summary>
  public static TheoryData<string> Scenes => new()
  {
    "Five balls", "Two spheres", "Sphere on the plane", "Cubes", "Bezier", "Sphere flake",
  };

  [Theory]
  [MemberData(nameof(Scenes))]
  public void Camera_rays_hit_the_same_node_on_the_tessellation_as_in_the_renderer(string name) =>
    AssertAgreement(name, global::Rendering.Scenes.Create(name));

  [Fact]
  public void Camera_rays_hit_the_same_transformed_sphere_cube_cylinder_and_torus() =>
    AssertAgreement("transformed solids", TessellationSurfaceTests.Solids().Scene);

  void AssertAgreement(string name, IRayScene scene)
  {
    SceneTessellation t = SceneTessellator.Tessellate(scene, new TessellationOptions { Width = Width, Height = Height });
    Assert.All(t.Parts, p => Assert.Null(p.CsgOperation));
    PreparedScene prepared = PreparedScene.Prepare(scene.Intersectable);
    List<PartTriangles> triangles = WorldTriangles(t, out Vector3d sceneMin, out Vector3d sceneMax);

    var renderer = new object?[Width, Height];
    var points = new Vector3d[Width, Height];
    var rays = new (Vector3d P0, Vector3d P1)[Width, Height];
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
      {
        scene.Camera!.GetRay(x + 0.5, y + 0.5, out Vector3d p0, out Vector3d p1);
        rays[x, y] = (p0, p1);
        Intersection? hit = prepared.FirstHit(p0, p1);
        renderer[x, y] = hit?.Solid;
        if (hit != null)
          points[x, y] = hit.CoordWorld;
      }

    int counted = 0, agree = 0, silhouettes = 0, beyond = 0;
    for (int y = 1; y < Height - 1; y++)
      for (int x = 1; x < Width - 1; x++)
      {
        object? solid = renderer[x, y];
        if (solid == null)
          continue;
        if (renderer[x - 1, y] != solid || renderer[x + 1, y] != solid || renderer[x, y - 1] != solid || renderer[x, y + 1] != solid)
        {
          silhouettes++;
          continue;
        }
        Vector3d p = points[x, y];
        if (p.X < sceneMin.X || p.Y < sceneMin.Y || p.Z < sceneMin.Z || p.X > sceneMax.X || p.Y > sceneMax.Y || p.Z > sceneMax.Z)
        {
          beyond++;
          continue;
        }
        counted++;
        if (ReferenceEquals(FirstTriangleHit(triangles, rays[x, y].P0, rays[x, y].P1), solid))
          agree++;
      }

    double share = agree / (double)counted;
    output.WriteLine($"{name}: {agree} of {counted} pixels agree ({share:P2}); left out {silhouettes} silhouette pixels, {beyond} beyond the patch");
    Assert.True(counted > Width * Height / 10, $"{name}: only {counted} pixels counted");
    Assert.True(share >= Required, $"{name}: only {agree} of {counted} pixels ({share:P2}) hit the same node");
  }

  sealed record PartTriangles(ISceneNode Node, Vector3d[] Corners, Vector3d Min, Vector3d Max);

  static List<PartTriangles> WorldTriangles(SceneTessellation t, out Vector3d sceneMin, out Vector3d sceneMax)
  {
    var list = new List<PartTriangles>();
    sceneMin = new Vector3d(double.PositiveInfinity);
    sceneMax = new Vector3d(double.NegativeInfinity);
    foreach (TessellatedPart part in t.Parts)
    {
      var corners = new Vector3d[part.Indices.Length];
      Vector3d min = new(double.PositiveInfinity), max = new(double.NegativeInfinity);
      for (int i = 0; i < corners.Length; i++)
      {
        corners[i] = part.WorldPosition(part.Indices[i]);
        min = Vector3d.ComponentMin(min, corners[i]);
        max = Vector3d.ComponentMax(max, corners[i]);
      }
      list.Add(new PartTriangles(part.Node, corners, min, max));
      sceneMin = Vector3d.ComponentMin(sceneMin, min);
      sceneMax = Vector3d.ComponentMax(sceneMax, max);
    }
    return list;
  }

  /// <summary>The node of the nearest triangle along the ray (Möller–Trumbore), both sides counted.</summary>
  static ISceneNode? FirstTriangleHit(List<PartTriangles> parts, Vector3d p0, Vector3d p1)
  {
    double best = double.PositiveInfinity;
    ISceneNode? node = null;
    foreach (PartTriangles part in parts)
    {
      if (!BoxHit(part.Min, part.Max, p0, p1, best))
        continue;
      Vector3d[] c = part.Corners;
      for (int k = 0; k < c.Length; k += 3)
      {
        Vector3d e1 = c[k + 1] - c[k], e2 = c[k + 2] - c[k];
        Vector3d h = Vector3d.Cross(p1, e2);
        double det = Vector3d.Dot(e1, h);
        if (Math.Abs(det) < 1e-18)
          continue;
        double inv = 1.0 / det;
        Vector3d s = p0 - c[k];
        double u = inv * Vector3d.Dot(s, h);
        if (u < 0.0 || u > 1.0)
          continue;
        Vector3d q = Vector3d.Cross(s, e1);
        double v = inv * Vector3d.Dot(p1, q);
        if (v < 0.0 || u + v > 1.0)
          continue;
        double tt = inv * Vector3d.Dot(e2, q);
        if (tt > 1e-9 && tt < best)
        {
          best = tt;
          node = part.Node;
        }
      }
    }
    return node;
  }

  static bool BoxHit(Vector3d min, Vector3d max, Vector3d p0, Vector3d p1, double tMax)
  {
    double t0 = 0.0, t1 = tMax;
    for (int a = 0; a < 3; a++)
    {
      double inv = 1.0 / p1[a];
      double ta = (min[a] - p0[a]) * inv, tb = (max[a] - p0[a]) * inv;
      if (ta > tb)
        (ta, tb) = (tb, ta);
      t0 = Math.Max(t0, ta);
      t1 = Math.Min(t1, tb);
      if (t0 > t1 + 1e-9)
        return false;
    }
    return true;
  }
}
