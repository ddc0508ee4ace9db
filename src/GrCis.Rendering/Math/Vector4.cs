using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>Single-precision 4D vector (OpenTK's name), for animated properties.</summary>
[Serializable]
public struct Vector4 : IEquatable<Vector4>
{
  public float X, Y, Z, W;

  public static readonly Vector4 Zero = new(0, 0, 0, 0);
  public static readonly Vector4 One = new(1, 1, 1, 1);

  public Vector4(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
  public Vector4(Vector3 v, float w) { X = v.X; Y = v.Y; Z = v.Z; W = w; }

  public Vector3 Xyz { readonly get => new(X, Y, Z); set { X = value.X; Y = value.Y; Z = value.Z; } }
  public readonly float LengthSquared => X * X + Y * Y + Z * Z + W * W;

  public readonly float Length => MathF.Sqrt(X * X + Y * Y + Z * Z + W * W);
  public static Vector4 Lerp(Vector4 a, Vector4 b, float t) => a + (b - a) * t;

  /// <summary>Row vector times matrix.</summary>
  public static Vector4 Transform(Vector4 vec, Matrix4 mat) => (Vector4)Vector4d.Transform(vec, mat);
  public static void Transform(ref Vector4 vec, ref Matrix4 mat, out Vector4 result) => result = Transform(vec, mat);
  public static Vector4 operator *(Vector4 vec, Matrix4 mat) => Transform(vec, mat);

  public static Vector4 operator +(Vector4 a, Vector4 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z, a.W + b.W);
  public static Vector4 operator -(Vector4 a, Vector4 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z, a.W - b.W);
  public static Vector4 operator *(Vector4 a, float s) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  public static Vector4 operator *(float s, Vector4 a) => new(a.X * s, a.Y * s, a.Z * s, a.W * s);
  public static bool operator ==(Vector4 a, Vector4 b) => a.Equals(b);
  public static bool operator !=(Vector4 a, Vector4 b) => !a.Equals(b);

  public readonly bool Equals(Vector4 other) => X == other.X && Y == other.Y && Z == other.Z && W == other.W;
  public override readonly bool Equals(object? obj) => obj is Vector4 v && Equals(v);
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z, W);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2}, {3})", X, Y, Z, W);
}
