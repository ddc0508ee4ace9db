using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The world-space test that lets a plane member skip its transform chain (<see cref="PlaneCull"/>): whenever it says
/// the ray leaves the plane, the plane's own kernel, through the same chain, reports neither a record nor an inside
/// state; and scenes with such planes answer as GrCis's lists do.
/// </summary>
public class PlaneCullTests
{
  /// <summary>A random world-to-local chain of one to three steps: rotations, (non-uniform) scales, shears, translations.</summary>
  static List<Matrix4d> RandomChain(Random r)
  {
    var path = new List<Matrix4d>();
    int steps = 1 + r.Next(3);
    for (int k = 0; k < steps; k++)
    {
      Matrix4d m = Matrix4d.Rotate(new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5), 6.3 * r.NextDouble());
      double scale = Math.Pow(10.0, 6.0 * r.NextDouble() - 3.0);
      m *= Matrix4d.Scale(scale * (0.5 + r.NextDouble()), scale * (0.5 + r.NextDouble()), scale * (0.5 + r.NextDouble()));
      if (r.Next(3) == 0)
        m.Row1.X += r.NextDouble() - 0.5;   // a shear
      m *= Matrix4d.CreateTranslation(Math.Pow(10.0, 4.0 * r.NextDouble() - 2.0) * new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5));
      path.Add(m);
    }
    return path;
  }

  /// <summary>The ray in the plane's space, through the chain as the prepared scene takes it.</summary>
  static (Vector3d P0, Vector3d P1) ToLocal(List<Matrix4d> path, Vector3d p0, Vector3d p1)
  {
    for (int k = 0; k < path.Count; k++)
    {
      Matrix4d t = path[k];
      CsgKernel.Transform(ref t, ref p0, ref p1);
    }
    return (p0, p1);
  }

  static Vector3d ToWorld(List<Matrix4d> path, Vector3d local)
  {
    Matrix4d worldToLocal = Matrix4d.Identity;
    foreach (Matrix4d m in path)
      worldToLocal *= m;
    return Vector3d.TransformPosition(local, worldToLocal.Inverted());
  }

  static Vector3d RandomVector(Random r) => new(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);

  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  [InlineData(3)]
  public void A_plane_said_to_be_left_has_neither_a_record_nor_an_inside_state(int seed)
  {
    var r = new Random(seed);
    int left = 0, fromSurface = 0;
    for (int n = 0; n < 40000; n++)
    {
      List<Matrix4d> path = RandomChain(r);
      var plane = new Plane();
      var m = new PreparedMember();
      PlaneCull.Build(ref m, path);
      Assert.True(m.HasPlaneZ);

      // Origins: anywhere, on the plane (where reflected and shadow rays start), or just off it on either side within a
      // few epsilons along the ray; directions of many lengths, some parallel to the plane or almost.
      Vector3d p1 = RandomVector(r) * Math.Pow(10.0, 4.0 * r.NextDouble() - 2.0);
      Vector3d p0;
      Vector3d onPlane = ToWorld(path, new Vector3d(20.0 * r.NextDouble() - 10.0, 20.0 * r.NextDouble() - 10.0, 0.0));
      switch (n % 5)
      {
        case 0:
          p0 = RandomVector(r) * 20.0;
          break;
        case 1:
        case 2:
          p0 = onPlane;
          break;
        case 3:
          p0 = onPlane - p1 * ((r.NextDouble() - 0.5) * 4.0 * Intersection.RAY_EPSILON / p1.Length);
          break;
        default:
          p0 = onPlane;
          var (_, d) = ToLocal(path, p0, p1);
          // Almost parallel: the direction's local z made tiny (of either sign) by mixing in its parallel part.
          p1 = ToWorld(path, new Vector3d(d.X, d.Y, d.Z * 1.0e-12 * (r.NextDouble() - 0.5))) - ToWorld(path, Vector3d.Zero);
          break;
      }
      double len2 = p1.LengthSquared;
      if (!PlaneCull.Leaves(m, p0, p1, len2))
        continue;
      left++;
      if (n % 5 is 1 or 2)
        fromSurface++;
      var (l0, l1) = ToLocal(path, p0, p1);
      bool has = plane.IntersectFirst(l0, l1, len2, out SolidRecord hit, out bool inside);
      Assert.False(has, $"record at t = {hit.T} for p0 {p0}, p1 {p1}");
      Assert.False(inside, $"inside state for p0 {p0}, p1 {p1}");
    }
    // Not vacuous: about half of the rays leave their plane, those from its surface among them.
    Assert.True(left > 10000 && fromSurface > 5000, $"{left} left, {fromSurface} from the surface");
  }

  [Fact]
  public void Rays_with_a_zero_or_not_finite_part_are_never_said_to_leave()
  {
    // The floor of the classic scenes: y = -1, facing +y (the chain is the inverse of its placement).
    var path = new List<Matrix4d> { (Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0)).Inverted() };
    var m = new PreparedMember();
    PlaneCull.Build(ref m, path);
    var above = new Vector3d(0.0, 1.0, 0.0);
    Assert.False(PlaneCull.Leaves(m, above, Vector3d.Zero, 0.0));
    Assert.False(PlaneCull.Leaves(m, above, new Vector3d(1.0, 0.0, 0.0), 1.0));
    Assert.False(PlaneCull.Leaves(m, new Vector3d(double.NaN, 1.0, 0.0), Vector3d.UnitY, 1.0));
    Assert.False(PlaneCull.Leaves(m, above, new Vector3d(0.0, double.PositiveInfinity, 0.0), double.PositiveInfinity));
    Assert.False(PlaneCull.Leaves(m, new Vector3d(0.0, -2.0, 0.0), Vector3d.UnitY, 1.0));   // from below, towards it
    Assert.True(PlaneCull.Leaves(m, above, Vector3d.UnitY, 1.0));
    Assert.True(PlaneCull.Leaves(m, new Vector3d(0.3, -1.0, 0.2), new Vector3d(0.1, 2.0, 0.0), 4.01));   // from on it, upwards
  }

  [Fact]
  public void A_chain_that_is_not_finite_gets_no_estimate()
  {
    var path = new List<Matrix4d> { Matrix4d.Scale(1.0e300) * Matrix4d.Scale(1.0e300) };
    var m = new PreparedMember();
    PlaneCull.Build(ref m, path);
    Assert.False(m.HasPlaneZ);
  }

  [Theory]
  [InlineData(11)]
  [InlineData(12)]
  public void Scenes_with_infinite_planes_answer_as_the_lists(int seed)
  {
    // Two infinite planes (a floor and a tilted one under a scaled chain), a glass-like ball and an opaque one; rays
    // from anywhere, and from hit points onwards (shadow, reflected and refracted rays start there).
    var r = new Random(seed);
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new Plane(), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
    var tilted = new CSGInnerNode(SetOperation.Union);
    tilted.InsertChild(new Plane(), Matrix4d.Rotate(new Vector3d(1.0, 0.3, 0.2), 1.1) * Matrix4d.CreateTranslation(0.0, 0.0, 4.0));
    root.InsertChild(tilted, Matrix4d.Scale(1.5, 0.7, 1.2));
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    root.InsertChild(new Sphere(), Matrix4d.Scale(1.2) * Matrix4d.CreateTranslation(1.5, 0.2, 2.4));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(2, ps.UnboundedCount);
    var lists = new SceneLists(root);
    int hits = 0;
    for (int n = 0; n < 30000; n++)
    {
      Vector3d p0 = RandomVector(r) * 12.0;
      Vector3d p1 = RandomVector(r) * (0.1 + 3.0 * r.NextDouble());
      if (n % 2 == 1 && lists.FirstHit(p0, p1) is Intersection start)
      {
        p0 = start.CoordWorld;
        p1 = n % 4 == 1 ? RandomVector(r) * (0.01 + 5.0 * r.NextDouble()) : new Vector3d(-5.0, 4.0, -3.0) - p0;
      }
      hits += PreparedSceneTests.AssertSameAnswers(lists, ps, p0, p1, compareEnter: true).Hit ? 1 : 0;
    }
    Assert.True(hits > 6000, $"{hits} hits");
  }
}
