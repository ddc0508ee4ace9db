using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's 16-bit IEEE 754 float (1 sign, 5 exponent, 10 mantissa bits), for vertex data. The conversions are .NET's
/// <see cref="System.Half"/> ones (round to nearest even; out of range gives ±infinity). Code that also imports
/// <c>System</c> must write <c>OpenTK.Mathematics.Half</c> or <c>System.Half</c> where it names the type, as with OpenTK 4.
/// </summary>
[Serializable]
public readonly struct Half : IEquatable<Half>, IComparable<Half>, IFormattable
{
  readonly ushort bits;

  /// <summary>The size of a half in bytes: 2.</summary>
  public static readonly int SizeInBytes = 2;
  /// <summary>The most negative finite half, −65504, as a float.</summary>
  public static readonly float MinValue = (float)System.Half.MinValue;
  /// <summary>The largest finite half, 65504, as a float.</summary>
  public static readonly float MaxValue = (float)System.Half.MaxValue;
  /// <summary>The smallest positive half (a subnormal, 2^−24), as a float.</summary>
  public static readonly float Epsilon = (float)System.Half.Epsilon;
  /// <summary>The smallest positive normal value, 2^−14.</summary>
  public static readonly float MinNormalizedValue = 6.1035156e-5f;

  Half(ushort bits, bool _) => this.bits = bits;
  /// <summary>The float rounded to the nearest half (ties to even); out of range gives ±infinity.</summary>
  public Half(float f) => bits = BitConverter.HalfToUInt16Bits((System.Half)f);
  /// <summary>The double rounded to the nearest half (ties to even); out of range gives ±infinity.</summary>
  public Half(double d) => bits = BitConverter.HalfToUInt16Bits((System.Half)d);

  /// <param name="throwOnError">Throw when <paramref name="f"/> is NaN or outside the half range instead of giving NaN or ±infinity.</param>
  public Half(float f, bool throwOnError) : this(f)
  {
    if (!throwOnError) return;
    if (float.IsNaN(f)) throw new ArithmeticException("Half: NaN is not a number to convert.");
    if (float.IsFinite(f) && !float.IsFinite(ToSingle())) throw new ArithmeticException($"Half: {f} is outside ±{MaxValue}.");
  }

  /// <summary>The double converted through float, as <see cref="Half(float, bool)"/>.</summary>
  public Half(double d, bool throwOnError) : this((float)d, throwOnError)
  {
  }

  /// <summary>Whether the value is +0 or −0.</summary>
  public bool IsZero => (bits & 0x7fff) == 0;
  /// <summary>Whether the value is not a number.</summary>
  public bool IsNaN => System.Half.IsNaN(Value);
  /// <summary>Whether the value is +∞.</summary>
  public bool IsPositiveInfinity => System.Half.IsPositiveInfinity(Value);
  /// <summary>Whether the value is −∞.</summary>
  public bool IsNegativeInfinity => System.Half.IsNegativeInfinity(Value);

  System.Half Value => BitConverter.UInt16BitsToHalf(bits);

  /// <summary>The value as a float (exact).</summary>
  public float ToSingle() => (float)Value;

  /// <summary>The value rounded to the nearest half (ties to even); out of range gives ±infinity.</summary>
  public static explicit operator Half(float f) => new(f);
  /// <summary>The value rounded to the nearest half (ties to even); out of range gives ±infinity.</summary>
  public static explicit operator Half(double d) => new(d);
  /// <summary>The value widened to float (exact).</summary>
  public static implicit operator float(Half h) => h.ToSingle();
  /// <summary>The value widened to float (exact).</summary>
  public static implicit operator double(Half h) => h.ToSingle();

  /// <summary>The two bytes in the machine's byte order, as <see cref="BitConverter.GetBytes(short)"/> writes them.</summary>
  public static byte[] GetBytes(Half h) => BitConverter.GetBytes(h.bits);
  /// <summary>The half stored in the two bytes at <paramref name="startIndex"/>, in the machine's byte order (as
  /// <see cref="GetBytes(Half)"/> writes them).</summary>
  public static Half FromBytes(byte[] value, int startIndex) => new(BitConverter.ToUInt16(value, startIndex), true);

  /// <summary>Equal as numbers: +0 equals −0, NaN equals nothing.</summary>
  public bool Equals(Half other) => !IsNaN && !other.IsNaN && (bits == other.bits || (IsZero && other.IsZero));
  /// <inheritdoc/>
  public override bool Equals(object? obj) => obj is Half h && Equals(h);
  /// <inheritdoc/>
  public override int GetHashCode() => IsZero ? 0 : bits;
  /// <summary>Compares the values as floats (NaN sorts before every number).</summary>
  public int CompareTo(Half other) => ToSingle().CompareTo(other.ToSingle());
  /// <summary>Whether the two are equal, as <see cref="Equals(Half)"/> compares them.</summary>
  public static bool operator ==(Half left, Half right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Half)"/>.</summary>
  public static bool operator !=(Half left, Half right) => !left.Equals(right);

  /// <summary>The value as the equal <see cref="float"/> writes itself.</summary>
  public override string ToString() => ToSingle().ToString(CultureInfo.CurrentCulture);
  /// <summary>The value written as the equal float, with <paramref name="format"/> and
  /// <paramref name="formatProvider"/>.</summary>
  public string ToString(string? format, IFormatProvider? formatProvider) => ToSingle().ToString(format, formatProvider);
}
