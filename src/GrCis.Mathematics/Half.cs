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

  public static readonly int SizeInBytes = 2;
  public static readonly float MinValue = (float)System.Half.MinValue;
  public static readonly float MaxValue = (float)System.Half.MaxValue;
  public static readonly float Epsilon = (float)System.Half.Epsilon;
  /// <summary>The smallest positive normal value, 2^−14.</summary>
  public static readonly float MinNormalizedValue = 6.1035156e-5f;

  Half(ushort bits, bool _) => this.bits = bits;
  public Half(float f) => bits = BitConverter.HalfToUInt16Bits((System.Half)f);
  public Half(double d) => bits = BitConverter.HalfToUInt16Bits((System.Half)d);

  /// <param name="throwOnError">Throw when <paramref name="f"/> is NaN or outside the half range instead of giving NaN or ±infinity.</param>
  public Half(float f, bool throwOnError) : this(f)
  {
    if (!throwOnError) return;
    if (float.IsNaN(f)) throw new ArithmeticException("Half: NaN is not a number to convert.");
    if (float.IsFinite(f) && !float.IsFinite(ToSingle())) throw new ArithmeticException($"Half: {f} is outside ±{MaxValue}.");
  }

  public Half(double d, bool throwOnError) : this((float)d, throwOnError)
  {
  }

  public bool IsZero => (bits & 0x7fff) == 0;
  public bool IsNaN => System.Half.IsNaN(Value);
  public bool IsPositiveInfinity => System.Half.IsPositiveInfinity(Value);
  public bool IsNegativeInfinity => System.Half.IsNegativeInfinity(Value);

  System.Half Value => BitConverter.UInt16BitsToHalf(bits);

  public float ToSingle() => (float)Value;

  public static explicit operator Half(float f) => new(f);
  public static explicit operator Half(double d) => new(d);
  public static implicit operator float(Half h) => h.ToSingle();
  public static implicit operator double(Half h) => h.ToSingle();

  /// <summary>The two bytes in the machine's byte order, as <see cref="BitConverter.GetBytes(short)"/> writes them.</summary>
  public static byte[] GetBytes(Half h) => BitConverter.GetBytes(h.bits);
  public static Half FromBytes(byte[] value, int startIndex) => new(BitConverter.ToUInt16(value, startIndex), true);

  /// <summary>Equal as numbers: +0 equals −0, NaN equals nothing.</summary>
  public bool Equals(Half other) => !IsNaN && !other.IsNaN && (bits == other.bits || (IsZero && other.IsZero));
  public override bool Equals(object? obj) => obj is Half h && Equals(h);
  public override int GetHashCode() => IsZero ? 0 : bits;
  public int CompareTo(Half other) => ToSingle().CompareTo(other.ToSingle());
  public static bool operator ==(Half left, Half right) => left.Equals(right);
  public static bool operator !=(Half left, Half right) => !left.Equals(right);

  /// <summary>The value as the equal <see cref="float"/> writes itself.</summary>
  public override string ToString() => ToSingle().ToString(CultureInfo.CurrentCulture);
  public string ToString(string? format, IFormatProvider? formatProvider) => ToSingle().ToString(format, formatProvider);
}
