using System;
using System.Globalization;
using System.Runtime.CompilerServices;

namespace OpenTK.Mathematics;

/// <summary>
/// A 3D vector of doubles with OpenTK's names and semantics (public fields, row-vector
/// transforms), so GrCis scripts written against OpenTK compile unchanged.
/// </summary>
[Serializable]
[OpenTk3RefForms]
public partial struct Vector3d : IEquatable<Vector3d>
{
  /// <summary>The components x, y and z.</summary>
  public double X, Y, Z;

  /// <summary>The vector (0, 0, 0).</summary>
  public static readonly Vector3d Zero = new(0, 0, 0);
  /// <summary>The vector (1, 1, 1).</summary>
  public static readonly Vector3d One = new(1, 1, 1);
  /// <summary>The vector (1, 0, 0).</summary>
  public static readonly Vector3d UnitX = new(1, 0, 0);
  /// <summary>The vector (0, 1, 0).</summary>
  public static readonly Vector3d UnitY = new(0, 1, 0);
  /// <summary>The vector (0, 0, 1).</summary>
  public static readonly Vector3d UnitZ = new(0, 0, 1);
  /// <summary>The vector with every component +∞.</summary>
  public static readonly Vector3d PositiveInfinity = new(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity);
  /// <summary>The vector with every component −∞.</summary>
  public static readonly Vector3d NegativeInfinity = new(double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity);

  /// <summary>The vector (x, y, z).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public Vector3d(double x, double y, double z) { X = x; Y = y; Z = z; }
  /// <summary>A vector with every component equal to <paramref name="value"/>.</summary>
  public Vector3d(double value) { X = Y = Z = value; }
  /// <summary>The vector (v.X, v.Y, z).</summary>
  public Vector3d(Vector2d v, double z) { X = v.X; Y = v.Y; Z = z; }
  /// <summary>A copy of <paramref name="v"/>.</summary>
  public Vector3d(Vector3d v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The first three components of <paramref name="v"/> (w is dropped, not divided by).</summary>
  public Vector3d(Vector4d v) { X = v.X; Y = v.Y; Z = v.Z; }
  /// <summary>The single-precision vector widened to double (exact).</summary>
  public Vector3d(Vector3 v) { X = v.X; Y = v.Y; Z = v.Z; }

  /// <summary>The component with index 0 (X), 1 (Y) or 2 (Z); any other index throws
  /// <see cref="System.IndexOutOfRangeException"/>.</summary>
  public double this[int index]
  {
    readonly get => index switch { 0 => X, 1 => Y, 2 => Z, _ => throw new IndexOutOfRangeException($"Vector3d index {index} is outside 0..2.") };
    set
    {
      switch (index)
      {
        case 0: X = value; break;
        case 1: Y = value; break;
        case 2: Z = value; break;
        default: throw new IndexOutOfRangeException($"Vector3d index {index} is outside 0..2.");
      }
    }
  }

  /// <summary>The Euclidean length √(x² + y² + z²).</summary>
  public readonly double Length
  {
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    get => Math.Sqrt(X * X + Y * Y + Z * Z);
  }
  /// <summary>The squared length x² + y² + z² (no square root).</summary>
  public readonly double LengthSquared => X * X + Y * Y + Z * Z;
  /// <summary>The length as 1 / <see cref="MathHelper.InverseSqrtFast(double)"/> of the squared length; that function
  /// is exact here, so this equals <see cref="Length"/> up to rounding.</summary>
  public readonly double LengthFast => 1.0 / MathHelper.InverseSqrtFast(LengthSquared);

  /// <summary>The components (x, y) as a Vector2d; setting assigns them to X, Y in the same order.</summary>
  public Vector2d Xy { readonly get => new(X, Y); set { X = value.X; Y = value.Y; } }
  /// <summary>The components (x, z) as a Vector2d; setting assigns them to X, Z in the same order.</summary>
  public Vector2d Xz { readonly get => new(X, Z); set { X = value.X; Z = value.Y; } }
  /// <summary>The components (y, z) as a Vector2d; setting assigns them to Y, Z in the same order.</summary>
  public Vector2d Yz { readonly get => new(Y, Z); set { Y = value.X; Z = value.Y; } }
  /// <summary>The components (y, x) as a Vector2d; setting assigns them to Y, X in the same order.</summary>
  public Vector2d Yx { readonly get => new(Y, X); set { Y = value.X; X = value.Y; } }
  /// <summary>The components (z, x) as a Vector2d; setting assigns them to Z, X in the same order.</summary>
  public Vector2d Zx { readonly get => new(Z, X); set { Z = value.X; X = value.Y; } }
  /// <summary>The components (z, y) as a Vector2d; setting assigns them to Z, Y in the same order.</summary>
  public Vector2d Zy { readonly get => new(Z, Y); set { Z = value.X; Y = value.Y; } }

  // OpenTK's three-component swizzles.
  /// <summary>The components (x, z, y) as a Vector3d; setting assigns them to X, Z, Y in the same order.</summary>
  public Vector3d Xzy { readonly get => new(X, Z, Y); set { X = value.X; Z = value.Y; Y = value.Z; } }
  /// <summary>The components (y, x, z) as a Vector3d; setting assigns them to Y, X, Z in the same order.</summary>
  public Vector3d Yxz { readonly get => new(Y, X, Z); set { Y = value.X; X = value.Y; Z = value.Z; } }
  /// <summary>The components (y, z, x) as a Vector3d; setting assigns them to Y, Z, X in the same order.</summary>
  public Vector3d Yzx { readonly get => new(Y, Z, X); set { Y = value.X; Z = value.Y; X = value.Z; } }
  /// <summary>The components (z, x, y) as a Vector3d; setting assigns them to Z, X, Y in the same order.</summary>
  public Vector3d Zxy { readonly get => new(Z, X, Y); set { Z = value.X; X = value.Y; Y = value.Z; } }
  /// <summary>The components (z, y, x) as a Vector3d; setting assigns them to Z, Y, X in the same order.</summary>
  public Vector3d Zyx { readonly get => new(Z, Y, X); set { Z = value.X; Y = value.Y; X = value.Z; } }

  /// <summary>Normalises this vector in place (OpenTK semantics).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public void Normalize()
  {
    double s = 1.0 / Length;
    X *= s; Y *= s; Z *= s;
  }

  /// <summary>Normalizes in place, exactly as <see cref="Normalize()"/> does (no approximation is used).</summary>
  public void NormalizeFast() => Normalize();

  /// <summary>A unit-length copy of the vector; a zero vector gives NaN in every component.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public readonly Vector3d Normalized()
  {
    double s = 1.0 / Length;
    return new Vector3d(X * s, Y * s, Z * s);
  }

  /// <summary>A unit-length copy of the vector, as <see cref="Normalized()"/>; a zero vector gives NaN
  /// components.</summary>
  public static Vector3d Normalize(Vector3d v) => v.Normalized();
  /// <summary><see cref="Normalize(Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Vector3d v, out Vector3d result) => result = v.Normalized();
  /// <summary>A unit-length copy, the same as <see cref="Normalize(Vector3d)"/> (no approximation is used).</summary>
  public static Vector3d NormalizeFast(Vector3d v) => v.Normalized();

  /// <summary>The dot product: the sum of the products of corresponding components (x·x' + y·y' + …).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static double Dot(Vector3d a, Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
  /// <summary><see cref="Dot(Vector3d, Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Dot(in Vector3d a, in Vector3d b, out double result) => result = Dot(a, b);

  /// <summary>The cross product a × b = (a.y·b.z − a.z·b.y, a.z·b.x − a.x·b.z, a.x·b.y − a.y·b.x),
  /// right-handed.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d Cross(Vector3d a, Vector3d b) =>
    new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
  /// <summary><see cref="Cross(Vector3d, Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Cross(in Vector3d a, in Vector3d b, out Vector3d result) => result = Cross(a, b);

  /// <summary>The sum, component by component.</summary>
  public static Vector3d Add(Vector3d a, Vector3d b) => a + b;
  /// <summary>The difference, component by component.</summary>
  public static Vector3d Subtract(Vector3d a, Vector3d b) => a - b;
  /// <summary>Every component multiplied by the scalar.</summary>
  public static Vector3d Multiply(Vector3d a, double s) => a * s;
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector3d Multiply(Vector3d a, Vector3d b) => a * b;
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector3d Divide(Vector3d a, double s) => a / s;
  /// <summary>The component-wise quotient (x / x', y / y', …).</summary>
  public static Vector3d Divide(Vector3d a, Vector3d b) => a / b;

  /// <summary>The smaller of each pair of components.</summary>
  public static Vector3d ComponentMin(Vector3d a, Vector3d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));
  /// <summary>The larger of each pair of components.</summary>
  public static Vector3d ComponentMax(Vector3d a, Vector3d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));
  /// <summary>The shorter of the two vectors by squared length (OpenTK 3 compares lengths here, not components); on a
  /// tie, <paramref name="b"/>.</summary>
  public static Vector3d Min(Vector3d a, Vector3d b) => a.LengthSquared < b.LengthSquared ? a : b;
  /// <summary>The longer of the two vectors by squared length (OpenTK 3 compares lengths here, not components); on a
  /// tie, <paramref name="a"/>.</summary>
  public static Vector3d Max(Vector3d a, Vector3d b) => a.LengthSquared >= b.LengthSquared ? a : b;
  /// <summary>Each component clamped between the same components of <paramref name="min"/> and <paramref name="max"/>;
  /// min is tested first, and nothing throws when min &gt; max.</summary>
  public static Vector3d Clamp(Vector3d v, Vector3d min, Vector3d max) =>
    new(MathHelper.ClampComponent(v.X, min.X, max.X), MathHelper.ClampComponent(v.Y, min.Y, max.Y), MathHelper.ClampComponent(v.Z, min.Z, max.Z));
  /// <summary>The absolute value of every component.</summary>
  public static Vector3d Abs(Vector3d v) => new(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));

  /// <summary>The Euclidean distance |a − b| between two points.</summary>
  public static double Distance(Vector3d a, Vector3d b) => (a - b).Length;
  /// <summary>The squared distance |a − b|² between two points (no square root).</summary>
  public static double DistanceSquared(Vector3d a, Vector3d b) => (a - b).LengthSquared;

  /// <summary>Linear interpolation a + t·(b − a): a at t = 0, b at t = 1; t is not clamped.</summary>
  public static Vector3d Lerp(Vector3d a, Vector3d b, double t) => a + (b - a) * t;

  /// <summary>The point <c>a + u (b − a) + v (c − a)</c> of triangle abc.</summary>
  public static Vector3d BaryCentric(Vector3d a, Vector3d b, Vector3d c, double u, double v) =>
    a + (b - a) * u + (c - a) * v;

  /// <summary>Angle between two vectors in radians.</summary>
  public static double CalculateAngle(Vector3d a, Vector3d b)
  {
    double d = Dot(a, b) / (a.Length * b.Length);
    return Math.Acos(Math.Clamp(d, -1.0, 1.0));
  }

  /// <summary>Row vector times matrix, ignoring translation: <c>(v, 0) * m</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformVector(Vector3d v, Matrix4d m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z);
  /// <summary><see cref="TransformVector(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformVector(in Vector3d v, in Matrix4d m, out Vector3d result) => result = TransformVector(v, m);

  /// <summary>Row vector times matrix with translation: <c>(v, 1) * m</c>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformPosition(Vector3d v, Matrix4d m) => new(
    v.X * m.Row0.X + v.Y * m.Row1.X + v.Z * m.Row2.X + m.Row3.X,
    v.X * m.Row0.Y + v.Y * m.Row1.Y + v.Z * m.Row2.Y + m.Row3.Y,
    v.X * m.Row0.Z + v.Y * m.Row1.Z + v.Z * m.Row2.Z + m.Row3.Z);
  /// <summary><see cref="TransformPosition(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void TransformPosition(in Vector3d v, in Matrix4d m, out Vector3d result) => result = TransformPosition(v, m);

  /// <summary>Transforms a normal by the inverse transpose of <paramref name="m"/>; a singular m throws, as in OpenTK 3.</summary>
  public static Vector3d TransformNormal(Vector3d n, Matrix4d m) => TransformNormalInverse(n, Matrix4d.Invert(m));

  /// <summary>Transforms a normal, given the already inverted matrix: <c>invM * n</c> as a column.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d TransformNormalInverse(Vector3d n, Matrix4d invM) => new(
    n.X * invM.Row0.X + n.Y * invM.Row0.Y + n.Z * invM.Row0.Z,
    n.X * invM.Row1.X + n.Y * invM.Row1.Y + n.Z * invM.Row1.Z,
    n.X * invM.Row2.X + n.Y * invM.Row2.Y + n.Z * invM.Row2.Z);

  /// <summary>OpenTK 3's name: the vector as a point (w = 1), times the matrix, without the perspective divide.</summary>
  public static Vector3d Transform(Vector3d vec, Matrix4d mat) => TransformPosition(vec, mat);
  /// <summary><see cref="Transform(Vector3d, Matrix4d)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Transform(in Vector3d vec, in Matrix4d mat, out Vector3d result) => result = TransformPosition(vec, mat);

  /// <summary>Row vector times a 3×3 matrix.</summary>
  public static Vector3d Transform(Vector3d vec, Matrix3d mat) => vec * mat;

  /// <summary>The point (w = 1) times the matrix, <c>(v, 1) * m</c>, divided by the resulting w: the homogeneous
  /// transform with the perspective divide.</summary>
  public static Vector3d TransformPerspective(Vector3d v, Matrix4d m)
  {
    Vector4d r = Vector4d.Transform(new Vector4d(v, 1.0), m);
    return new Vector3d(r.X / r.W, r.Y / r.W, r.Z / r.W);
  }

  /// <summary>Rotates <paramref name="v"/> by the unit quaternion <paramref name="q"/> (q v q⁻¹, evaluated with two
  /// cross products).</summary>
  public static Vector3d Transform(Vector3d v, Quaterniond q)
  {
    Vector3d u = q.Xyz;
    Vector3d t = 2.0 * Cross(u, v);
    return v + q.W * t + Cross(u, t);
  }

  /// <summary>The sum, component by component.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator +(Vector3d a, Vector3d b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
  /// <summary>The difference, component by component.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator -(Vector3d a, Vector3d b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
  /// <summary>The vector with every component negated.</summary>
  public static Vector3d operator -(Vector3d a) => new(-a.X, -a.Y, -a.Z);
  /// <summary>Every component multiplied by the scalar.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator *(Vector3d a, double s) => new(a.X * s, a.Y * s, a.Z * s);
  /// <summary>Every component multiplied by the scalar.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static Vector3d operator *(double s, Vector3d a) => new(a.X * s, a.Y * s, a.Z * s);
  /// <summary>The component-wise product (x·x', y·y', …), not a dot product.</summary>
  public static Vector3d operator *(Vector3d a, Vector3d b) => new(a.X * b.X, a.Y * b.Y, a.Z * b.Z);
  /// <summary>Every component divided by the scalar.</summary>
  public static Vector3d operator /(Vector3d a, double s) { double inv = 1.0 / s; return new(a.X * inv, a.Y * inv, a.Z * inv); }
  /// <summary>The component-wise quotient (x / x', y / y', z / z').</summary>
  public static Vector3d operator /(Vector3d a, Vector3d b) => new(a.X / b.X, a.Y / b.Y, a.Z / b.Z);
  /// <summary>Whether the two are equal, as <see cref="Equals(Vector3d)"/> compares them.</summary>
  public static bool operator ==(Vector3d a, Vector3d b) => a.Equals(b);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Vector3d)"/>.</summary>
  public static bool operator !=(Vector3d a, Vector3d b) => !a.Equals(b);

  /// <summary>Each component rounded to float.</summary>
  public static explicit operator Vector3(Vector3d v) => new((float)v.X, (float)v.Y, (float)v.Z);
  /// <summary>The single-precision vector widened to double (exact).</summary>
  public static implicit operator Vector3d(Vector3 v) => new(v.X, v.Y, v.Z);
  /// <summary>The vector of a tuple, for <c>Vector3d v = (1, 2, 3);</c>.</summary>
  public static implicit operator Vector3d((double X, double Y, double Z) t) => new(t.X, t.Y, t.Z);

  /// <summary>Splits the vector into its components, for <c>var (x, y, z) = v;</c>.</summary>
  public readonly void Deconstruct(out double x, out double y, out double z) { x = X; y = Y; z = Z; }

  /// <summary>Whether every component equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Vector3d other) => X == other.X && Y == other.Y && Z == other.Z;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Vector3d v && Equals(v);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(X, Y, Z);
  /// <inheritdoc/>
  public override readonly string ToString() =>
    string.Format(CultureInfo.CurrentCulture, "({0}, {1}, {2})", X, Y, Z);
}
