using System;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// One node of a mesh's eight-wide tree (<see cref="MeshBvh"/>): up to eight child boxes side by side in floats (lane l
/// of each vector is child l), so one 256-bit step tests eight boxes (<see cref="FloatStep"/>). The boxes are the
/// binary tree's (padded) double boxes rounded outward, so each contains its double box: a box test on them may keep
/// more, never fewer. Lane l is an inner child (<see cref="Count"/>[l] == 0, node <see cref="Index"/>[l]) or a leaf
/// (<see cref="Count"/>[l] triangle blocks from <see cref="Index"/>[l] on). An unused lane holds the empty box
/// (min +∞, max −∞), which no line crosses.
/// </summary>
internal struct MeshNode
{
  public const int Width = 8;

  // Planes in this order, so a per-ray plane number 0…5 picks a field (FloatStep): min x, y, z, then max x, y, z.
  public Vector256<float> MinX, MinY, MinZ, MaxX, MaxY, MaxZ;
  public Lanes Index, Count;

  /// <summary>Eight ints, one per lane.</summary>
  [InlineArray(Width)]
  public struct Lanes
  {
    int lane;
  }

  /// <summary>
  /// The walks' code for lane <paramref name="lane"/> of this node, numbered <paramref name="self"/>: an inner child's
  /// node number (≥ 0), or for a leaf ~(self·8 + lane), from which <see cref="MeshBvh"/> reads the leaf's blocks.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly int Child(int self, int lane) => Count[lane] == 0 ? Index[lane] : ~(self * Width + lane);

  /// <summary>
  /// <see cref="Child"/> of all eight lanes at once (a vector select, no branch per lane), for a walk that spills them
  /// once and pushes several.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly Vector256<int> Children(int self)
  {
    Vector256<int> index = Unsafe.As<Lanes, Vector256<int>>(ref Unsafe.AsRef(in Index));
    Vector256<int> count = Unsafe.As<Lanes, Vector256<int>>(ref Unsafe.AsRef(in Count));
    Vector256<int> leaf = ~(Vector256.Create(self * Width) + Vector256.Create(0, 1, 2, 3, 4, 5, 6, 7));
    return Vector256.ConditionalSelect(Vector256.Equals(count, Vector256<int>.Zero), index, leaf);
  }

  /// <summary>Every lane empty (min +∞, max −∞).</summary>
  public void Clear()
  {
    MinX = MinY = MinZ = Vector256.Create(float.PositiveInfinity);
    MaxX = MaxY = MaxZ = Vector256.Create(float.NegativeInfinity);
  }

  /// <summary>Puts <paramref name="box"/> grown by <paramref name="pad"/> in lane <paramref name="lane"/>, rounded outward to floats.</summary>
  public void SetBox(int lane, in BvhNode box, double pad)
  {
    MinX = MinX.WithElement(lane, Down(box.MinX - pad));
    MinY = MinY.WithElement(lane, Down(box.MinY - pad));
    MinZ = MinZ.WithElement(lane, Down(box.MinZ - pad));
    MaxX = MaxX.WithElement(lane, Up(box.MaxX + pad));
    MaxY = MaxY.WithElement(lane, Up(box.MaxY + pad));
    MaxZ = MaxZ.WithElement(lane, Up(box.MaxZ + pad));
  }

  /// <summary>The largest float ≤ <paramref name="x"/> (−∞ below the float range; NaN stays NaN).</summary>
  // Branch-free: a walk's set-up rounds a handful of values per ray, and which way a value rounds to nearest is a coin
  // toss the branch predictor loses half the time. A float that rounded up moves one step down: its bits less one when
  // positive (+∞ becomes the largest float), plus one when negative or −0 (−0 becomes −ε); +0 never rounds up from below.
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static float Down(double x)
  {
    float f = (float)x;
    int bits = BitConverter.SingleToInt32Bits(f);
    int step = ((double)f > x ? 1 : 0) * ((bits >> 31) | 1);
    return BitConverter.Int32BitsToSingle(bits - step);
  }

  /// <summary>The smallest float ≥ <paramref name="x"/> (+∞ above the float range; NaN stays NaN).</summary>
  // As Down, mirrored: a float that rounded down moves one step up (+0 becomes +ε; −0 never rounds down from above).
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static float Up(double x)
  {
    float f = (float)x;
    int bits = BitConverter.SingleToInt32Bits(f);
    int step = ((double)f < x ? 1 : 0) * ((bits >> 31) | 1);
    return BitConverter.Int32BitsToSingle(bits + step);
  }

  /// <summary><see cref="Down(double)"/> of each of four doubles, the same floats.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector128<float> Down(Vector256<double> x)
  {
    Vector128<float> f = Narrow(x);
    Vector128<int> bits = f.AsInt32();
    return (bits - (RoundedPast(Widen(f), x) & ((bits >> 31) | Vector128<int>.One))).AsSingle();
  }

  /// <summary><see cref="Up(double)"/> of each of four doubles, the same floats.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector128<float> Up(Vector256<double> x)
  {
    Vector128<float> f = Narrow(x);
    Vector128<int> bits = f.AsInt32();
    return (bits + (RoundedPast(x, Widen(f)) & ((bits >> 31) | Vector128<int>.One))).AsSingle();
  }

  // All ones in the lanes where a > b (a 32-bit mask per double lane).
  static Vector128<int> RoundedPast(Vector256<double> a, Vector256<double> b)
  {
    Vector256<long> m = Vector256.GreaterThan(a, b).AsInt64();
    return Vector256.Narrow(m, m).GetLower();
  }

  /// <summary>Each double rounded to the nearest float (the conversion <c>(float)x</c> does).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector128<float> Narrow(Vector256<double> x) =>
    Avx.IsSupported ? Avx.ConvertToVector128Single(x) : Vector256.Narrow(x, x).GetLower();

  /// <summary>Each float as a double (exact).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector256<double> Widen(Vector128<float> f) =>
    Avx.IsSupported ? Avx.ConvertToVector256Double(f) : Vector256.Create(Vector128.WidenLower(f), Vector128.WidenUpper(f));
}
