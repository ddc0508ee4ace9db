using System;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering;

/// <summary>
/// The eight-box step of a mesh walk in floats: per axis one fused multiply–add for the near plane and one for the far
/// plane of all eight boxes (the plane is picked once per ray by the sign of the direction), so a node costs six FMAs, four
/// min/max and a compare. Conservative: each box's interval contains the one the exact double slab test
/// (<see cref="Accel.WideNode.Cross"/> on the double boxes) computes, so it keeps every box that test keeps, with a near
/// end no later and a far end no earlier; the double triangle tests decide every answer.
/// </summary>
/// <remarks>
/// Why it contains (per axis; u = 2^-24, the float rounding unit; M = the largest |coordinate| of the float boxes on the
/// axis; o, inv = 1/d the ray's doubles; set-up in the constructor):
/// <list type="bullet">
/// <item>The float box contains the double box (rounded outward), and its slab the double slab: for inv &gt; 0 the near plane
/// b ≤ b_d, so b·inv ≤ b_d·inv; for inv &lt; 0 the near plane is the max plane, b ≥ b_d, and again b·inv ≤ b_d·inv.</item>
/// <item>The double test gives t_d = (b_d − o)·inv·(1 + δ), |δ| ≤ 2.0001·2^-53: t_d ≥ (b_d − o)·inv − 2^-52.9·(|o| + M)·|inv|.</item>
/// <item>invf = float(inv) = inv·(1 + ε), |ε| ≤ u (|inv| in [2^-100, 2^100]: a normal float). The step computes
/// fl(b·invf + cN) with one rounding (FMA) and cN ≤ −o·invf − pad, pad = 4u·(|o| + M)·|inv|, so
/// t ≤ (b − o)·invf − pad + u·|b·invf + cN| ≤ (b_d − o)·inv + u(|o| + M)|inv| − pad + u((|o| + M)|inv|(1 + u) + pad).</item>
/// <item>Hence t ≤ t_d − pad(1 − u) + (2u + u² + 2^-52.9)(|o| + M)|inv| &lt; t_d − 1.99u(|o| + M)|inv|: the margin also covers
/// the double rounding of cN's set-up (relative 2^-52) and an underflow of the FMA (absolute 2^-150, while
/// (|o| + M)|inv| ≥ 2^-100 is required). No overflow: every value stays below 2^102.</item>
/// <item>The far plane likewise with cF ≥ −o·invf + pad: t ≥ t_d. The min and max over the axes are exact, so near ≤ the
/// double near and far ≥ the double far, and a box the double test keeps (near_d ≤ far_d) is kept.</item>
/// </list>
/// A ray outside these bounds (a zero or ∞ direction component, an origin or a mesh beyond 2^100 in (|o| + M)|inv|,
/// NaN) gets no float step: its walk falls back to <see cref="DoubleStep"/>, decided once per ray.
/// An unused lane (min +∞, max −∞) gives near +∞ and far −∞ whatever the sign: never crossed.
/// </remarks>
internal readonly struct FloatStep : IMeshBoxStep
{
  readonly Vector256<float> ix, iy, iz, nx, ny, nz, fx, fy, fz;
  readonly nint px, py, pz, qx, qy, qz;   // near and far plane of each axis (byte offset of the MeshNode field)

  const double Two100 = (double)(1L << 50) * (1L << 50);
  const double Lowest = 1.0 / Two100;
  const double Pad = 1.0 / (1 << 22);   // 4u

  /// <summary>
  /// True when the float step can bound the ray (origin o, inverse direction inv) in a tree whose float boxes reach at
  /// most <paramref name="mx"/>, <paramref name="my"/>, <paramref name="mz"/> in absolute value; false when the ray (or
  /// the mesh) lies outside the bounds of the proof (see the remarks). Decided once per ray, the three axes at once.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Bounded(in MeshLine line, double mx, double my, double mz)
  {
    // Ordered comparisons, so that NaN fails too; the fourth lane (inverse 1, |o| + m = 1) passes.
    Vector256<double> a = Vector256.Abs(Vector256.Create(line.Ix, line.Iy, line.Iz, 1.0));
    Vector256<double> s = (Vector256.Abs(Vector256.Create(line.Ox, line.Oy, line.Oz, 0.0)) + Vector256.Create(mx, my, mz, 1.0)) * a;
    Vector256<double> low = Vector256.Create(Lowest), high = Vector256.Create(Two100);
    var inRange = Vector256.GreaterThanOrEqual(a, low) & Vector256.LessThanOrEqual(a, high) &
                  Vector256.GreaterThanOrEqual(s, low) & Vector256.LessThanOrEqual(s, high);
    return inRange.ExtractMostSignificantBits() == 0b1111;
  }

  /// <summary>The step for a ray <see cref="Bounded"/> accepts (the same bounds).</summary>
  /// <remarks>
  /// Per axis (lanes x, y, z of one vector; the same arithmetic in the same order as one axis at a time): the float
  /// inverse, the near and far offsets cN ≤ −o·invf − pad and cF ≥ −o·invf + pad, the near plane (0 min, 3 max).
  /// </remarks>
  [SkipLocalsInit]
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public FloatStep(in MeshLine line, double mx, double my, double mz)
  {
    Vector256<double> o = Vector256.Create(line.Ox, line.Oy, line.Oz, 0.0);
    Vector256<double> inv = Vector256.Create(line.Ix, line.Iy, line.Iz, 1.0);
    Vector128<float> f = MeshNode.Narrow(inv);
    Vector256<double> oi = o * MeshNode.Widen(f);
    Vector256<double> pad = Vector256.Create(Pad) * (Vector256.Abs(o) + Vector256.Create(mx, my, mz, 0.0)) * Vector256.Abs(inv);
    Vector128<float> near = MeshNode.Down(-oi - pad), far = MeshNode.Up(-oi + pad);
    ix = Vector256.Create(f.GetElement(0));
    iy = Vector256.Create(f.GetElement(1));
    iz = Vector256.Create(f.GetElement(2));
    nx = Vector256.Create(near.GetElement(0));
    ny = Vector256.Create(near.GetElement(1));
    nz = Vector256.Create(near.GetElement(2));
    fx = Vector256.Create(far.GetElement(0));
    fy = Vector256.Create(far.GetElement(1));
    fz = Vector256.Create(far.GetElement(2));
    // Field numbers (0…2 min, 3…5 max): the near plane is the min plane where inv > 0, the far plane the axis's other
    // one; kept as byte offsets, so a node's step needs no index arithmetic.
    int negative = (int)Vector256.LessThanOrEqual(inv, Vector256<double>.Zero).ExtractMostSignificantBits();
    int x = (negative & 1) * 3, y = ((negative >> 1) & 1) * 3, z = ((negative >> 2) & 1) * 3;
    int size = Unsafe.SizeOf<Vector256<float>>();
    px = x * size;
    qx = (3 - x) * size;
    py = (y + 1) * size;
    qy = (4 - y) * size;
    pz = (z + 2) * size;
    qz = (5 - z) * size;
  }

  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public int Cross(ref readonly MeshNode n, out Vector256<float> near, out Vector256<float> far)
  {
    ref Vector256<float> p = ref Unsafe.AsRef(in n.MinX);
    near = Vector256.MaxNative(Vector256.MaxNative(Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, px), ix, nx),
                                                   Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, py), iy, ny)),
                               Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, pz), iz, nz));
    far = Vector256.MinNative(Vector256.MinNative(Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, qx), ix, fx),
                                                  Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, qy), iy, fy)),
                              Vector256.FusedMultiplyAdd(Unsafe.AddByteOffset(ref p, qz), iz, fz));
    return (int)Vector256.LessThanOrEqual(near, far).ExtractMostSignificantBits();
  }
}
