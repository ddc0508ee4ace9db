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
  /// the mesh) lies outside the bounds of the proof (see the remarks). Cheap scalar checks, decided once per ray.
  /// </summary>
  public static bool Bounded(in MeshLine line, double mx, double my, double mz) =>
    InRange(line.Ox, line.Ix, mx) && InRange(line.Oy, line.Iy, my) && InRange(line.Oz, line.Iz, mz);

  // Written so that NaN fails too.
  static bool InRange(double o, double inv, double m)
  {
    double a = Math.Abs(inv), s = (Math.Abs(o) + m) * a;
    return a >= Lowest && a <= Two100 && s >= Lowest && s <= Two100;
  }

  /// <summary>The step for a ray <see cref="Bounded"/> accepts (the same bounds).</summary>
  [SkipLocalsInit]
  public FloatStep(in MeshLine line, double mx, double my, double mz)
  {
    Axis(line.Ox, line.Ix, mx, out ix, out nx, out fx, out int x);
    Axis(line.Oy, line.Iy, my, out iy, out ny, out fy, out int y);
    Axis(line.Oz, line.Iz, mz, out iz, out nz, out fz, out int z);
    // Field numbers (0…2 min, 3…5 max; the far plane is the axis's other one) as byte offsets: no index arithmetic per node.
    int size = Unsafe.SizeOf<Vector256<float>>();
    px = x * size;
    qx = (3 - x) * size;
    py = (y + 1) * size;
    qy = (4 - y) * size;
    pz = (z + 2) * size;
    qz = (5 - z) * size;
  }

  // One axis: float inverse, the near and far offsets cN ≤ −o·invf − pad and cF ≥ −o·invf + pad, the near plane (0 min, 3 max).
  static void Axis(double o, double inv, double m, out Vector256<float> vinv, out Vector256<float> near, out Vector256<float> far, out int plane)
  {
    float f = (float)inv;
    double oi = o * f, pad = Pad * (Math.Abs(o) + m) * Math.Abs(inv);
    vinv = Vector256.Create(f);
    near = Vector256.Create(MeshNode.Down(-oi - pad));
    far = Vector256.Create(MeshNode.Up(-oi + pad));
    plane = inv > 0.0 ? 0 : 3;
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
