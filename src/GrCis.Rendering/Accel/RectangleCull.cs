using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The bounded rectangles among a prepared scene's open members (library <see cref="Plane"/>s), four at a time in
/// world space: a conservative test that proves, for most of them, that the exact test in local space would change
/// nothing, so only the rest go through their transform chain. A rectangle is skipped when, allowing for a
/// generous bound on the difference between this estimate and the chain's arithmetic, the ray leaves its front
/// side before the first accepted t (no record, not inside), meets it from the front beyond the best t so far (an
/// entry that cannot win), or its line misses the rectangle. Every other rectangle is tested exactly, so the
/// answers (and their bits) are those of the exact test alone.
/// </summary>
/// <remarks>
/// Per rectangle the local coordinates are affine in the world ray: <c>l(p) = o + A p</c>, with <c>o</c> and the
/// columns of <c>A</c> taken through the same chain. The chain rounds differently, by at most a few units in the
/// last place of its terms' magnitudes; <see cref="Gamma"/> times the chain's absolute magnitude
/// (<c>K · max(1, |p|∞)</c>) bounds that difference by a factor of about a thousand.
/// </remarks>
internal sealed class RectangleCull
{
  /// <summary>Relative bound on the difference between the composite estimate and the chain's arithmetic.</summary>
  const double Gamma = 1.0e-12;

  /// <summary>Four rectangles side by side (lane l of each vector is rectangle l).</summary>
  internal struct Group
  {
    // Rows of the composite map into local space: z (the plane's normal), x and y; W is the translation.
    public Vector256<double> Zx, Zy, Zz, Zw, Xx, Xy, Xz, Xw, Yx, Yy, Yz, Yw;
    public Vector256<double> XMin, XMax, YMin, YMax;

    /// <summary>The chain's absolute magnitude (max row sum of the product of absolute matrices, translation included).</summary>
    public Vector256<double> K;

    public WideNode.Lanes Member;

    /// <summary>Bit l set: lane l holds a rectangle.</summary>
    public int Valid;
  }

  readonly Group[] groups;

  RectangleCull(Group[] groups, int count)
  {
    this.groups = groups;
    Count = count;
  }

  /// <summary>Rectangles handled here.</summary>
  public int Count { get; }

  /// <summary>Groups of four (the last may be partly empty).</summary>
  public ReadOnlySpan<Group> Groups => groups;

  /// <summary>
  /// True for a member this test may stand in for: a library plane (its records those of <see cref="Plane"/>),
  /// a rectangle with finite bounds, under a chain whose composite is finite.
  /// </summary>
  static bool Eligible(in PreparedMember m)
  {
    if (m.RecordSolid is not Plane plane || plane.Triangle || m.Csg != null || !m.RecordSolid.RecordsMatchIntersect)
      return false;
    if (!LibraryTypes.HasPlaneGeometry(plane))
      return false;
    return double.IsFinite(plane.XMin) && double.IsFinite(plane.XMax) && double.IsFinite(plane.YMin) && double.IsFinite(plane.YMax);
  }

  /// <summary>
  /// Takes the eligible members of <paramref name="open"/> (member indices) into a cull, in their order; the rest
  /// are returned in <paramref name="rest"/>. Null when none is eligible.
  /// </summary>
  public static RectangleCull? Build(PreparedMember[] members, Matrix4d[] chain, int[] open, out int[] rest)
  {
    var taken = new List<(int Member, Vector3d O, Vector3d Ax, Vector3d Ay, Vector3d Az, double K)>();
    var others = new List<int>();
    foreach (int index in open)
    {
      ref PreparedMember m = ref members[index];
      if (!Eligible(m) || !Composite(m, chain, out Vector3d o, out Vector3d ax, out Vector3d ay, out Vector3d az, out double k))
      {
        others.Add(index);
        continue;
      }
      taken.Add((index, o, ax, ay, az, k));
    }
    rest = others.ToArray();
    if (taken.Count == 0)
      return null;

    var groups = new Group[(taken.Count + WideNode.Width - 1) / WideNode.Width];
    for (int g = 0; g < groups.Length; g++)
    {
      var group = new Group();
      for (int lane = 0; lane < WideNode.Width; lane++)
      {
        int n = g * WideNode.Width + lane;
        if (n >= taken.Count)
        {
          group.Member[lane] = -1;
          continue;
        }
        var (member, o, ax, ay, az, k) = taken[n];
        var plane = (Plane)members[member].RecordSolid!;
        // l.c(p) = o.c + p.x ax.c + p.y ay.c + p.z az.c, for local coordinate c.
        group.Zx = group.Zx.WithElement(lane, ax.Z);
        group.Zy = group.Zy.WithElement(lane, ay.Z);
        group.Zz = group.Zz.WithElement(lane, az.Z);
        group.Zw = group.Zw.WithElement(lane, o.Z);
        group.Xx = group.Xx.WithElement(lane, ax.X);
        group.Xy = group.Xy.WithElement(lane, ay.X);
        group.Xz = group.Xz.WithElement(lane, az.X);
        group.Xw = group.Xw.WithElement(lane, o.X);
        group.Yx = group.Yx.WithElement(lane, ax.Y);
        group.Yy = group.Yy.WithElement(lane, ay.Y);
        group.Yz = group.Yz.WithElement(lane, az.Y);
        group.Yw = group.Yw.WithElement(lane, o.Y);
        group.XMin = group.XMin.WithElement(lane, plane.XMin);
        group.XMax = group.XMax.WithElement(lane, plane.XMax);
        group.YMin = group.YMin.WithElement(lane, plane.YMin);
        group.YMax = group.YMax.WithElement(lane, plane.YMax);
        group.K = group.K.WithElement(lane, k);
        group.Member[lane] = member;
        group.Valid |= 1 << lane;
      }
      groups[g] = group;
    }
    return new RectangleCull(groups, taken.Count);
  }

  /// <summary>The member's chain as one affine map (origin and the images of the axes) and its absolute magnitude.</summary>
  static bool Composite(in PreparedMember m, Matrix4d[] chain, out Vector3d o, out Vector3d ax, out Vector3d ay, out Vector3d az, out double k)
  {
    o = Vector3d.Zero;
    ax = Vector3d.UnitX;
    ay = Vector3d.UnitY;
    az = Vector3d.UnitZ;
    Vector3d abs = Vector3d.One, unused = Vector3d.Zero;
    int end = m.ChainStart + m.ChainCount;
    for (int i = m.ChainStart; i < end; i++)
    {
      ref Matrix4d t = ref chain[i];
      Vector3d d = Vector3d.Zero;
      CsgKernel.Transform(ref t, ref o, ref d);
      Vector3d p = Vector3d.Zero;
      CsgKernel.Transform(ref t, ref p, ref ax);
      p = Vector3d.Zero;
      CsgKernel.Transform(ref t, ref p, ref ay);
      p = Vector3d.Zero;
      CsgKernel.Transform(ref t, ref p, ref az);
      Matrix4d a = Absolute(t);
      CsgKernel.Transform(ref a, ref abs, ref unused);
    }
    k = Math.Max(abs.X, Math.Max(abs.Y, abs.Z));
    return Finite(o) && Finite(ax) && Finite(ay) && Finite(az) && double.IsFinite(k);
  }

  static bool Finite(in Vector3d v) => double.IsFinite(v.X) && double.IsFinite(v.Y) && double.IsFinite(v.Z);

  static Matrix4d Absolute(in Matrix4d t) => new(
    Math.Abs(t.M11), Math.Abs(t.M12), Math.Abs(t.M13), Math.Abs(t.M14),
    Math.Abs(t.M21), Math.Abs(t.M22), Math.Abs(t.M23), Math.Abs(t.M24),
    Math.Abs(t.M31), Math.Abs(t.M32), Math.Abs(t.M33), Math.Abs(t.M34),
    Math.Abs(t.M41), Math.Abs(t.M42), Math.Abs(t.M43), Math.Abs(t.M44));

  /// <summary>
  /// The lanes of <paramref name="g"/> that must be tested exactly for the ray <c>p0 + t d</c> (bit l: lane l).
  /// <paramref name="best"/> is the query's pruning bound (entries beyond it cannot win), <paramref name="accept"/>
  /// the smallest accepted t (<c>RAY_EPSILON / |d|</c>), <paramref name="scale"/> <c>max(1, |p0|∞)</c> and
  /// <paramref name="dirScale"/> <c>|d|∞</c>.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static int MustTest(in Group g, Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                             Vector256<double> dx, Vector256<double> dy, Vector256<double> dz,
                             double scale, double dirScale, double accept, double best)
  {
    Vector256<double> gk = g.K * Vector256.Create(Gamma);
    Vector256<double> e0 = gk * Vector256.Create(scale), ed = gk * Vector256.Create(dirScale);
    Vector256<double> z0 = g.Zx * ox + g.Zy * oy + g.Zz * oz + g.Zw;
    Vector256<double> vz = g.Zx * dx + g.Zy * dy + g.Zz * dz;

    // Leaving the front side (local dz > 0 for sure) with t ≤ 0.999·accept for sure: no accepted record, not inside.
    Vector256<double> tau = Vector256.Create(0.999 * accept);
    Vector256<double> behind = Vector256.GreaterThan(vz, ed) & Vector256.LessThanOrEqual(e0 - z0, tau * (vz - ed));

    // Entering from the front (local dz < 0 for sure) beyond max(best, 1.001·accept) for sure: an accepted entry that
    // cannot win (or no record at all).
    Vector256<double> bound = Vector256.Create(Math.Max(best, 1.001 * accept));
    Vector256<double> beyond = Vector256.LessThan(vz, -ed) & Vector256.GreaterThan(z0 - e0, bound * (ed - vz));
    int open = g.Valid & ~(int)(behind | beyond).ExtractMostSignificantBits();
    if (open == 0)
      return 0;   // shadow rays mostly end here: every rectangle behind them or beyond the light

    // The line misses the rectangle for sure (then Plane's test has no record at any t); needs |dz| well above its error.
    // One division: with ed·|1/dz| < 1/2, 1/(|dz| − ed) ≤ |1/dz|·(1 + 2 ed |1/dz|); 1.01 covers the rounding of 1/dz.
    Vector256<double> avz = Vector256.Abs(vz);
    Vector256<double> inv = Vector256<double>.One / vz;
    Vector256<double> ainv = Vector256.Abs(inv);
    Vector256<double> t = -z0 * inv;
    Vector256<double> at = Vector256.Abs(t);
    Vector256<double> common = e0 + at * ed;
    Vector256<double> et = common * ainv * (Vector256<double>.One + (ed + ed) * ainv) * Vector256.Create(1.01) + at * Vector256.Create(Gamma);
    Vector256<double> x0 = g.Xx * ox + g.Xy * oy + g.Xz * oz + g.Xw;
    Vector256<double> vx = g.Xx * dx + g.Xy * dy + g.Xz * dz;
    Vector256<double> y0 = g.Yx * ox + g.Yy * oy + g.Yz * oz + g.Yw;
    Vector256<double> vy = g.Yx * dx + g.Yy * dy + g.Yz * dz;
    Vector256<double> tvx = t * vx, tvy = t * vy;
    Vector256<double> x = x0 + tvx, y = y0 + tvy;
    Vector256<double> ex = common + et * (Vector256.Abs(vx) + ed) + (Vector256.Abs(x0) + Vector256.Abs(tvx)) * Vector256.Create(Gamma);
    Vector256<double> ey = common + et * (Vector256.Abs(vy) + ed) + (Vector256.Abs(y0) + Vector256.Abs(tvy)) * Vector256.Create(Gamma);
    Vector256<double> outside = Vector256.LessThan(x + ex, g.XMin) | Vector256.GreaterThan(x - ex, g.XMax) |
                                Vector256.LessThan(y + ey, g.YMin) | Vector256.GreaterThan(y - ey, g.YMax);
    Vector256<double> misses = Vector256.GreaterThan(avz, ed + ed) & outside;

    // NaN anywhere (a non-finite ray) compares false: such lanes are tested.
    return open & ~(int)misses.ExtractMostSignificantBits();
  }
}
