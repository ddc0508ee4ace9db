using System;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The closest-record query keeps its records in slots that the kernels write into directly: a member tested after
/// the winner (a farther one, or one the ray starts inside) must not overwrite the winner's record, and a list
/// member's hit beside it must win and lose as the lists say. The hit points and normals, not only T, are compared.
/// </summary>
public class QueryRecordSlotTests
{
  static void AssertSameHit(SceneLists lists, PreparedScene ps, Vector3d p0, Vector3d p1)
  {
    Intersection? a = lists.FirstHit(p0, p1);
    Intersection? b = ps.FirstHit(p0, p1);
    Assert.Equal(a == null, b == null);
    if (a == null || b == null)
      return;
    a.Complete();
    b.Complete();   // a hit the faithful path answered (rays from inside a ball) comes uncompleted, as the lists give it
    Assert.Same(a.Solid, b.Solid);
    Assert.Equal(a.T, b.T);
    Assert.Equal(a.Enter, b.Enter);
    Assert.Equal(a.CoordWorld, b.CoordWorld);
    Assert.Equal(a.Normal, b.Normal);
    Assert.Equal(lists.AnyHit(p0, p1), ps.AnyHit(p0, p1));
  }

  [Theory]
  [InlineData(false)]
  [InlineData(true)]
  public void A_row_of_balls_keeps_the_nearest_record_whichever_end_the_ray_comes_from(bool withScriptSolid)
  {
    // Four balls in a row along x (tested side by side), overlapping pairs, a floor; optionally a script sphere in the row.
    var root = new CSGInnerNode(SetOperation.Union);
    for (int k = 0; k < 4; k++)
      root.InsertChild(new Sphere(), Matrix4d.Scale(0.6 + 0.1 * k) * Matrix4d.CreateTranslation(1.5 * k - 2.0, 0.1 * k, 0.0));
    if (withScriptSolid)
      root.InsertChild(new ScriptSphere(), Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(0.25, 0.0, 0.3));
    root.InsertChild(new Plane(), Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0, -1.5, 0));
    PreparedScene ps = PreparedScene.Prepare(root);
    Assert.Equal(4, ps.CulledBallCount);
    var lists = new SceneLists(root);

    var r = new Random(withScriptSolid ? 5 : 4);
    for (int n = 0; n < 4000; n++)
    {
      // Along the row from either end, from inside a ball, and from hit points onwards.
      double side = n % 2 == 0 ? 1.0 : -1.0;
      var p0 = n % 3 == 0
        ? new Vector3d(1.5 * r.Next(4) - 2.0 + 0.3 * (r.NextDouble() - 0.5), 0.2 * (r.NextDouble() - 0.5), 0.2 * (r.NextDouble() - 0.5))
        : new Vector3d(6.0 * side, 0.6 * (r.NextDouble() - 0.5), 0.6 * (r.NextDouble() - 0.5));
      var p1 = new Vector3d(-side, 0.1 * (r.NextDouble() - 0.5), 0.1 * (r.NextDouble() - 0.5)) * (0.5 + r.NextDouble());
      for (int bounce = 0; bounce < 3; bounce++)
      {
        AssertSameHit(lists, ps, p0, p1);
        Intersection? i = lists.FirstHit(p0, p1);
        if (i == null)
          break;
        p0 = i.CoordWorld;
        p1 = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
      }
    }
  }
}
