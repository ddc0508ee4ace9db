using System;
using System.Collections.Generic;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The side-by-side test of a few balls (<see cref="SphereCull"/>): a ball it leaves out has neither a record nor an
/// inside state for the ray, in particular the ball a ray leaves from its surface; and such rays get the lists' answers.
/// </summary>
public class SphereCullTests
{
  static Vector3d RandomVector(Random r) => new(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);

  /// <summary>A direction of length 10^-3 … 10^2 (the acceptance test uses the world |d|²).</summary>
  static Vector3d RandomDirection(Random r) => RandomVector(r).Normalized() * Math.Pow(10.0, 5.0 * r.NextDouble() - 3.0);

  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  public void A_ball_left_out_has_neither_a_record_nor_an_inside_state(int seed)
  {
    var r = new Random(seed);
    int leaving = 0, leavingLeftOut = 0;
    for (int n = 0; n < 30000; n++)
    {
      // One ball under a random similarity; its member as the prepared scene builds it (padded world ball).
      double radius = Math.Pow(10.0, 3.0 * r.NextDouble() - 1.5);
      Vector3d centre = RandomVector(r) * Math.Pow(10.0, 3.0 * r.NextDouble());
      Matrix4d toWorld = Matrix4d.Scale(radius) * Matrix4d.Rotate(RandomVector(r), 6.3 * r.NextDouble()) * Matrix4d.CreateTranslation(centre);
      Matrix4d chain = toWorld.Inverted();
      Vector3d c = Vector3d.TransformPosition(Vector3d.Zero, toWorld);
      double padded = radius * (1.0 + 1.0e-6) + 1.0e-12;
      var members = new[] { new PreparedMember { CullCenter = c, CullRadius2 = padded * padded } };
      SphereCull cull = SphereCull.Build(members, new List<int> { 0 })!;

      // Rays from its surface (outwards, inwards, along it), from just off it within a few epsilons, and from anywhere.
      Vector3d p1 = RandomDirection(r);
      Vector3d onSurface = Vector3d.TransformPosition(RandomVector(r).Normalized(), toWorld);
      Vector3d normal = (onSurface - c).Normalized();
      Vector3d p0 = (n % 4) switch
      {
        0 => onSurface,
        1 => onSurface + p1 * ((r.NextDouble() - 0.5) * 6.0 * Intersection.RAY_EPSILON / p1.Length),
        2 => c + RandomVector(r) * (4.0 * radius),
        _ => onSurface,
      };
      if (n % 4 == 3 && Vector3d.Dot(normal, p1) < 0.0)
        p1 = -p1;   // outwards
      double len2 = p1.LengthSquared;

      int mask = SphereCull.MustTest(cull.Groups[0], Vector256.Create(p0.X), Vector256.Create(p0.Y), Vector256.Create(p0.Z),
                                     Vector256.Create(p1.X), Vector256.Create(p1.Y), Vector256.Create(p1.Z), len2, double.PositiveInfinity);
      bool leaves = n % 4 == 3 || n % 4 == 0 && Vector3d.Dot(normal, p1) > 0.0;
      leaving += leaves ? 1 : 0;
      if ((mask & 1) != 0)
        continue;
      leavingLeftOut += leaves ? 1 : 0;
      Vector3d l0 = p0, l1 = p1;
      CsgKernel.Transform(ref chain, ref l0, ref l1);
      bool has = new Sphere().IntersectFirst(l0, l1, len2, out SolidRecord hit, out bool inside);
      Assert.False(has, $"record at t = {hit.T} (p0 {p0}, p1 {p1})");
      Assert.False(inside, $"inside state (p0 {p0}, p1 {p1})");
    }
    // Rays leaving the ball from its surface are left out (not only misses and balls behind the origin), all but the
    // grazing ones, whose line stays in the padded ball a little longer.
    Assert.True(leaving > 8000 && leavingLeftOut > 0.85 * leaving, $"{leavingLeftOut} of {leaving} leaving from the surface left out");
  }

  [Theory]
  [InlineData(3)]
  [InlineData(5)]
  public void Rays_leaving_a_ball_from_its_surface_get_the_lists_answers(int count)
  {
    var r = new Random(count);
    var root = new CSGInnerNode(SetOperation.Union);
    var balls = new List<(Vector3d C, double R)>();
    for (int k = 0; k < count; k++)
    {
      double radius = 0.3 + r.NextDouble();
      Vector3d c = RandomVector(r) * 5.0;
      root.InsertChild(new Sphere(), Matrix4d.Scale(radius) * Matrix4d.CreateTranslation(c));
      balls.Add((c, radius));
    }
    root.InsertChild(new Plane(), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -3.0, 0.0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(count, ps.CulledBallCount);
    var lists = new SceneLists(root);
    int hits = 0;
    for (int n = 0; n < 20000; n++)
    {
      var (c, radius) = balls[r.Next(balls.Count)];
      Vector3d p0 = RandomVector(r) * 12.0, p1 = RandomDirection(r);
      if (lists.FirstHit(p0, c - p0) is Intersection start)
      {
        // From the hit point: outwards (reflected, shadow rays), inwards (refracted), to another ball, to a light;
        // sometimes moved along the ray by a few epsilons either way.
        p0 = start.CoordWorld;
        p1 = (n % 4) switch
        {
          0 => p1,
          1 => balls[r.Next(balls.Count)].C - p0,
          2 => new Vector3d(-5.0, 4.0, -3.0) - p0,
          _ => (p0 - c) * Math.Pow(10.0, 4.0 * r.NextDouble() - 2.0),
        };
        if (n % 3 == 0)
          p0 += p1 * ((r.NextDouble() - 0.5) * 6.0 * Intersection.RAY_EPSILON / p1.Length);
      }
      hits += PreparedSceneTests.AssertSameAnswers(lists, ps, p0, p1, compareEnter: true).Hit ? 1 : 0;
    }
    Assert.True(hits > 5000, $"{hits} hits");
  }
}
