using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The closed members of a small scene, when all of them are spheres under a similarity (their conservative world
/// bounding spheres, <see cref="PreparedMember.CullRadius2"/>), four at a time instead of a BVH: a member is skipped
/// when the ray's line misses its padded ball, the ball lies wholly behind the origin or within half the smallest accepted
/// t of it (a ray leaving the ball it starts on), or it starts beyond the best t so far, each for sure after allowing for
/// rounding. Such a member has no record the query could take, and it cannot
/// contain the origin, so (as for the BVH's pruning) the answer is that of testing every member exactly.
/// </summary>
internal sealed class SphereCull
{
  /// <summary>More closed members than this go into the BVH.</summary>
  public const int MaxMembers = 8;

  /// <summary>Four balls side by side (lane l of each vector is ball l).</summary>
  internal struct Group
  {
    public Vector256<double> Cx, Cy, Cz, R2, R;
    public WideNode.Lanes Member;

    /// <summary>Bit l set: lane l holds a ball.</summary>
    public int Valid;
  }

  readonly Group[] groups;

  SphereCull(Group[] groups, int count)
  {
    this.groups = groups;
    Count = count;
  }

  /// <summary>Balls handled here.</summary>
  public int Count { get; }

  /// <summary>Groups of four (the last may be partly empty).</summary>
  public ReadOnlySpan<Group> Groups => groups;

  /// <summary>The cull over <paramref name="bounded"/> (member indices), or null when they are too many or not all bounded by a ball.</summary>
  public static SphereCull? Build(PreparedMember[] members, List<int> bounded)
  {
    if (bounded.Count == 0 || bounded.Count > MaxMembers)
      return null;
    foreach (int index in bounded)
      if (!(members[index].CullRadius2 > 0.0) || !double.IsFinite(members[index].CullRadius2))
        return null;

    var groups = new Group[(bounded.Count + WideNode.Width - 1) / WideNode.Width];
    for (int g = 0; g < groups.Length; g++)
    {
      var group = new Group();
      for (int lane = 0; lane < WideNode.Width; lane++)
      {
        int n = g * WideNode.Width + lane;
        if (n >= bounded.Count)
        {
          group.Member[lane] = -1;
          continue;
        }
        ref PreparedMember m = ref members[bounded[n]];
        group.Cx = group.Cx.WithElement(lane, m.CullCenter.X);
        group.Cy = group.Cy.WithElement(lane, m.CullCenter.Y);
        group.Cz = group.Cz.WithElement(lane, m.CullCenter.Z);
        group.R2 = group.R2.WithElement(lane, m.CullRadius2);
        group.R = group.R.WithElement(lane, System.Math.Sqrt(m.CullRadius2));
        group.Member[lane] = bounded[n];
        group.Valid |= 1 << lane;
      }
      groups[g] = group;
    }
    return new SphereCull(groups, bounded.Count);
  }

  /// <summary>
  /// The lanes of <paramref name="g"/> that must be tested exactly for the ray <c>p0 + t d</c> (|d|² =
  /// <paramref name="dd"/>) when the best t so far is <paramref name="bestT"/>.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static int MustTest(in Group g, Vector256<double> ox, Vector256<double> oy, Vector256<double> oz,
                             Vector256<double> dx, Vector256<double> dy, Vector256<double> dz, double dd, double bestT)
  {
    Vector256<double> cx = g.Cx - ox, cy = g.Cy - oy, cz = g.Cz - oz;
    Vector256<double> b = cx * dx + cy * dy + cz * dz;
    Vector256<double> oo = cx * cx + cy * cy + cz * cz;
    Vector256<double> vdd = Vector256.Create(dd);
    Vector256<double> c = oo - g.R2;
    // The line misses the padded ball (the test MissesSphere makes): no record at any t. NaN compares false: tested.
    Vector256<double> bb = b * b;
    int open = g.Valid & ~(int)Vector256.GreaterThan(c * vdd, bb).ExtractMostSignificantBits();
    if (open == 0)
      return 0;
    // Only for a line near some ball (most rays of a small scene miss them all): |d|, and the bound
    // max(best t so far, just above the smallest accepted t).
    // One division: 1/|d| and its square stand for the quotients (a few ulps off, far inside the margins below).
    double invLength = 1.0 / Math.Sqrt(dd);
    double bound = Math.Max(bestT, 1.001 * Intersection.RAY_EPSILON * invLength);

    // Where the line crosses the ball, t ∈ [(b − s)/dd, (b + s)/dd]; the slack covers the rounding of both ends
    // (relative to the magnitudes |oc|·|d| ≤ |oc|₁·|d|, r·|d|, |b| and s the terms carry) by a wide margin.
    Vector256<double> s = Vector256.Sqrt(Vector256.Max(bb - vdd * c, Vector256<double>.Zero));
    Vector256<double> inv = Vector256.Create(invLength * invLength), len = Vector256.Create(Math.Sqrt(dd));
    Vector256<double> scale = (Vector256.Abs(cx) + Vector256.Abs(cy) + Vector256.Abs(cz) + g.R) * len + Vector256.Abs(b) + s;
    Vector256<double> slack = scale * inv * Vector256.Create(1.0e-9);
    Vector256<double> tin = (b - s) * inv, tout = (b + s) * inv;
    // Behind: every t of the ball below half the smallest accepted t (|t|·|d| < RAY_EPSILON / 2): its roots are not
    // accepted, so the kernel reports neither a record nor an inside state. This takes in the rays that leave the ball
    // they start on (shadow, reflected and outgoing refracted rays), not only balls wholly behind the origin.
    Vector256<double> near = Vector256.Create(0.5 * Intersection.RAY_EPSILON * invLength);
    Vector256<double> behind = Vector256.LessThan(tout + slack, near);
    Vector256<double> beyond = Vector256.GreaterThan(tin - slack, Vector256.Create(bound));
    return open & ~(int)(behind | beyond).ExtractMostSignificantBits();
  }
}
