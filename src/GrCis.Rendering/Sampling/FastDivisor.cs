using System;
using System.Runtime.CompilerServices;

namespace Rendering;

/// <summary>
/// Exact unsigned 32-bit division and remainder by a divisor fixed in advance, by multiplication (Lemire, Kaser and
/// Kurz 2019, "Faster remainder by direct computation"): the same quotient and remainder as <c>/</c> and <c>%</c> for
/// every dividend, without a hardware division per call.
/// </summary>
internal readonly struct FastDivisor
{
  readonly ulong multiplier;

  /// <summary>The divisor (at least 1).</summary>
  public readonly uint Value;

  public FastDivisor(uint divisor)
  {
    if (divisor == 0)
      throw new ArgumentOutOfRangeException(nameof(divisor), "a divisor must be at least 1");
    Value = divisor;
    // ⌈2⁶⁴ / d⌉; for d = 1 it wraps to 0 and the methods answer directly.
    multiplier = ulong.MaxValue / divisor + 1;
  }

  /// <summary><paramref name="a"/> / <see cref="Value"/>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public uint Divide(uint a) => Value == 1 ? a : (uint)Math.BigMul(multiplier, a, out _);

  /// <summary><paramref name="a"/> % <see cref="Value"/>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public uint Remainder(uint a) => Value == 1 ? 0 : (uint)Math.BigMul(multiplier * a, Value, out _);
}
