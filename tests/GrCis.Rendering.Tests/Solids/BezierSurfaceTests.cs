using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Xunit.Abstractions;
using static GrCis.Rendering.Tests.Solids.SolidTestSupport;

namespace GrCis.Rendering.Tests.Solids;

public class BezierSurfaceTests
{
  readonly ITestOutputHelper output;

  public BezierSurfaceTests(ITestOutputHelper output) => this.output = output;

  /// <summary>The classic "Bezier" scene's net: 4 rows × 7 columns (K = 1, L = 2).</summary>
  static readonly double[] SceneNet =
  {
    0, 0, 3, 1, 0, 3, 2, 0, 3, 3, 0, 3, 4, 0, 3, 5, 0, 3, 6, 0, 3,
    0, 0, 2, 1, 0, 2, 2, 3, 2, 3, 3, 2, 4, 3, 2, 5, 0, 2, 6, 0, 2,
    0, 0, 1, 1, 0, 1, 2, 0, 1, 3, 1.5, 1, 4, 3, 1, 5, 0, 1, 6, 0, 1,
    0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0, 5, 0, 0, 6, 0, 0,
  };

  /// <summary>A planar net P(row i, column j) = (j, i, 0): S(u, v) = (3u, 3v, 0).</summary>
  static double[] PlanarNet()
  {
    var v = new double[48];
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
      {
        v[3 * (4 * i + j)] = j;
        v[3 * (4 * i + j) + 1] = i;
      }
    return v;
  }

  [Fact]
  public void Bezier_planar_patch_hit_has_exact_t_texture_and_normal()
  {
    var b = new BezierSurface(1, 1, PlanarNet());
    Assert.True(b.PreciseNormals);
    var root = Place(b, Matrix4d.Identity);
    Vector3d p0 = new Vector3d(1.5, 0.75, 5), p1 = new Vector3d(0, 0, -2);
    var hits = Hits(root, p0, p1);
    Assert.Single(hits);
    Assert.Equal(2.5, hits[0].T, 12);
    Assert.True(hits[0].Enter && hits[0].Front);   // normal Su × Sv = +z, ray goes −z
    Intersection i = First(root, p0, p1);
    Assert.Equal(0.5, i.TextureCoord.X, 10);
    Assert.Equal(0.25, i.TextureCoord.Y, 10);
    AssertVector(Vector3d.UnitZ, i.Normal, 1e-12);
    AssertVector(Vector3d.UnitX, i.TangentU, 1e-12);
    Assert.False(Hits(b, new Vector3d(1.5, 0.75, -5), new Vector3d(0, 0, 1))[0].Front);
    Assert.Null(b.Intersect(new Vector3d(3.5, 1, 5), new Vector3d(0, 0, -1)));
  }

  [Fact]
  public void Bezier_second_patch_texture_starts_at_l()
  {
    var b = new BezierSurface(1, 2, SceneNet);
    var root = Place(b, Matrix4d.Identity);
    // Column 5..6 region of the second patch is flat at y = 0 near the edge x ≈ 6.
    Intersection i = First(root, new Vector3d(5.9, 5, 0.1), new Vector3d(0, -1, 0));
    Assert.InRange(i.TextureCoord.X, 1.0, 2.0);
    Assert.InRange(i.TextureCoord.Y, 0.0, 1.0);
    AssertOnRay(i, new Vector3d(5.9, 5, 0.1), new Vector3d(0, -1, 0), 1e-9);
  }

  [Fact]
  public void Bezier_bad_arguments_throw()
  {
    Assert.Throws<ArgumentOutOfRangeException>(() => new BezierSurface(0, 1, PlanarNet()));
    Assert.Throws<ArgumentException>(() => new BezierSurface(1, 2, PlanarNet()));
  }

  [Fact]
  public void Bezier_hits_agree_with_a_fine_tessellation_of_the_scene_surface()
  {
    var b = new BezierSurface(1, 2, SceneNet);
    // Reference: 2 × 256 × 256 triangles per patch, evaluated independently with de Casteljau.
    const int N = 256;
    var tris = new List<(Vector3d a, Vector3d b, Vector3d c)>();
    for (int l = 0; l < 2; l++)
    {
      var grid = new Vector3d[N + 1, N + 1];
      for (int i = 0; i <= N; i++)
        for (int j = 0; j <= N; j++)
          grid[i, j] = DeCasteljau(l, (double)j / N, (double)i / N);
      for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
        {
          tris.Add((grid[i, j], grid[i, j + 1], grid[i + 1, j + 1]));
          tris.Add((grid[i, j], grid[i + 1, j + 1], grid[i + 1, j]));
        }
    }

    var rnd = new Random(5);
    int rays = 0, agree = 0, hitsTotal = 0;
    double maxErr = 0;
    for (int n = 0; n < 150; n++)
    {
      Vector3d target = new Vector3d(6 * rnd.NextDouble(), 3 * rnd.NextDouble(), 3 * rnd.NextDouble());
      Vector3d p0 = target + new Vector3d(rnd.NextDouble() - 0.5, rnd.NextDouble() + 0.2, rnd.NextDouble() - 0.5).Normalized() * 10;
      Vector3d p1 = target - p0;
      var ours = Hits(b, p0, p1);
      AssertSorted(ours);
      var reference = new List<double>();
      foreach (var (ta, tb, tc) in tris)
        if (RayTriangle(p0, p1, ta, tb, tc, out double t))
          reference.Add(t);
      reference.Sort();
      var distinct = new List<double>();
      foreach (double t in reference)
        if (distinct.Count == 0 || t - distinct[^1] > 1e-7)
          distinct.Add(t);
      rays++;
      hitsTotal += ours.Count;
      if (distinct.Count != ours.Count)
        continue;
      agree++;
      for (int k = 0; k < ours.Count; k++)
      {
        maxErr = System.Math.Max(maxErr, System.Math.Abs(ours[k].T - distinct[k]) * p1.Length);
        // Every reported hit lies exactly on the surface at its (u, v): check via completion.
        ours[k].Complete();
      }
    }
    output.WriteLine($"bezier: {rays} rays, {hitsTotal} hits, counts agree on {agree}, max distance difference to the 256² tessellation {maxErr:E2}");
    Assert.True(agree >= rays * 97 / 100, $"counts agree on only {agree} of {rays} rays");
    Assert.True(maxErr < 1e-3, $"max error {maxErr}");
    Assert.True(hitsTotal > 100);
  }

  static Vector3d DeCasteljau(int patchL, double u, double v)
  {
    var rows = new Vector3d[4];
    for (int i = 0; i < 4; i++)
    {
      var pts = new Vector3d[4];
      for (int j = 0; j < 4; j++)
      {
        int o = 3 * (i * 7 + 3 * patchL + j);
        pts[j] = new Vector3d(SceneNet[o], SceneNet[o + 1], SceneNet[o + 2]);
      }
      rows[i] = Reduce(pts, u);
    }
    return Reduce(rows, v);
  }

  static Vector3d Reduce(Vector3d[] p, double t)
  {
    var q = (Vector3d[])p.Clone();
    for (int r = 3; r > 0; r--)
      for (int i = 0; i < r; i++)
        q[i] = (1 - t) * q[i] + t * q[i + 1];
    return q[0];
  }

  static bool RayTriangle(Vector3d o, Vector3d d, Vector3d a, Vector3d b, Vector3d c, out double t)
  {
    t = 0;
    Vector3d e1 = b - a, e2 = c - a;
    Vector3d p = Vector3d.Cross(d, e2);
    double det = Vector3d.Dot(e1, p);
    if (det == 0) return false;
    Vector3d s = o - a;
    double u = Vector3d.Dot(s, p) / det;
    if (u < 0 || u > 1) return false;
    Vector3d q = Vector3d.Cross(s, e1);
    double v = Vector3d.Dot(d, q) / det;
    if (v < 0 || u + v > 1) return false;
    t = Vector3d.Dot(e2, q) / det;
    return true;
  }

  [Fact]
  public void Bezier_world_normal_follows_the_parent_transform()
  {
    var root = Place(new BezierSurface(1, 1, PlanarNet()), Matrix4d.RotateX(-System.Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0));
    // Local +z → world +y; the surface lies in the floor y = −1.
    Vector3d p0 = new Vector3d(1, 3, -1), p1 = new Vector3d(0, -1, 0);
    Intersection i = First(root, p0, p1);
    AssertOnRay(i, p0, p1, 1e-9);
    AssertVector(Vector3d.UnitY, i.Normal, 1e-12);
  }

  [Fact]
  public void Bezier_fast_first_record_equals_the_list_scan_on_random_rays()
  {
    var b = new BezierSurface(1, 2, SceneNet);
    Assert.True(b.RecordsMatchIntersect);
    var rnd = new Random(77);
    int accepted = 0, startInside = 0;
    for (int r = 0; r < 5_000; r++)
    {
      // From around the surface (some on it: rays leaving a hit point), in every direction, any length.
      Vector3d p0 = new(8 * rnd.NextDouble() - 1, 6 * rnd.NextDouble() - 3, 5 * rnd.NextDouble() - 1);
      Vector3d p1 = new Vector3d(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5) * (0.2 + 3 * rnd.NextDouble());
      if (r % 4 == 3 && b.Intersect(p0, p1) is { First: not null } onto)
        p0 += onto.First.Value.T * p1;
      double len2 = p1.LengthSquared * (r % 2 == 0 ? 1.0 : 0.25);   // the world ray's length may differ

      // The list scan IRecordSolid.IntersectFirst promises.
      LinkedList<Intersection>? list = b.Intersect(p0, p1);
      Intersection? want = null;
      bool wantInside = false;
      if (list != null && list.First != null)
      {
        wantInside = !list.First.Value.Enter;
        foreach (Intersection i in list)
        {
          if (i.T > 0.0 && i.T * i.T * len2 > Intersection.RAY_EPSILON2)
          {
            want = i;
            break;
          }
          wantInside = i.Enter;
        }
      }

      bool got = b.IntersectFirst(p0, p1, len2, out global::Rendering.Accel.SolidRecord h, out bool inside);
      Assert.Equal(want != null, got);
      Assert.Equal(wantInside, inside);
      startInside += inside ? 1 : 0;
      if (want == null)
        continue;
      accepted++;
      Intersection mine = ((global::Rendering.Accel.IRecordSolid)b).CreateIntersection(h);
      Assert.Equal(want.T, mine.T);
      Assert.Equal(want.Enter, mine.Enter);
      Assert.Equal(want.Front, mine.Front);
      Assert.Equal(want.CoordLocal, mine.CoordLocal);
      want.Complete();
      mine.Complete();
      Assert.Equal(want.Normal, mine.Normal);
      Assert.Equal(want.TextureCoord, mine.TextureCoord);
    }
    output.WriteLine($"{accepted} accepted records, {startInside} rays starting inside");
    Assert.True(accepted > 500 && startInside > 100, $"{accepted} accepted, {startInside} inside: the rays miss the surface");
  }
}

