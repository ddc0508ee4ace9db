using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK's double-precision 3×3 matrix (row vectors: <c>v' = v · M</c>): a rotation or scale without
/// translation. Arithmetic goes through <see cref="Matrix4d"/>.
/// </summary>
[OpenTk3RefForms]
public partial struct Matrix3d : IEquatable<Matrix3d>
{
  public Vector3d Row0, Row1, Row2;

  public static readonly Matrix3d Identity = new(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ);
  public static readonly Matrix3d Zero = new(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero);

  public Matrix3d(Vector3d row0, Vector3d row1, Vector3d row2) => (Row0, Row1, Row2) = (row0, row1, row2);

  public Matrix3d(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22)
    : this(new Vector3d(m00, m01, m02), new Vector3d(m10, m11, m12), new Vector3d(m20, m21, m22))
  {
  }

  /// <summary>The upper-left 3×3 part.</summary>
  public Matrix3d(Matrix4d m) : this(m.Row0.Xyz, m.Row1.Xyz, m.Row2.Xyz)
  {
  }

  public double M11 { readonly get => Row0.X; set => Row0.X = value; }
  public double M12 { readonly get => Row0.Y; set => Row0.Y = value; }
  public double M13 { readonly get => Row0.Z; set => Row0.Z = value; }
  public double M21 { readonly get => Row1.X; set => Row1.X = value; }
  public double M22 { readonly get => Row1.Y; set => Row1.Y = value; }
  public double M23 { readonly get => Row1.Z; set => Row1.Z = value; }
  public double M31 { readonly get => Row2.X; set => Row2.X = value; }
  public double M32 { readonly get => Row2.Y; set => Row2.Y = value; }
  public double M33 { readonly get => Row2.Z; set => Row2.Z = value; }

  /// <summary>The six-term expansion OpenTK 3 evaluates, so <see cref="Inverted"/> finds the same matrices singular.</summary>
  public readonly double Determinant =>
    Row0.X * Row1.Y * Row2.Z + Row0.Y * Row1.Z * Row2.X + Row0.Z * Row1.X * Row2.Y
    - Row0.Z * Row1.Y * Row2.X - Row0.X * Row1.Z * Row2.Y - Row0.Y * Row1.X * Row2.Z;

  readonly Matrix4d To4() => new(new Vector4d(Row0, 0), new Vector4d(Row1, 0), new Vector4d(Row2, 0), Vector4d.UnitW);

  public static Matrix3d CreateRotationX(double angle) => new(Matrix4d.CreateRotationX(angle));
  public static Matrix3d CreateRotationY(double angle) => new(Matrix4d.CreateRotationY(angle));
  public static Matrix3d CreateRotationZ(double angle) => new(Matrix4d.CreateRotationZ(angle));
  public static Matrix3d CreateFromAxisAngle(Vector3d axis, double angle) => new(Matrix4d.CreateFromAxisAngle(axis, angle));
  public static Matrix3d CreateScale(double s) => CreateScale(s, s, s);
  public static Matrix3d CreateScale(double x, double y, double z) => new(x, 0, 0, 0, y, 0, 0, 0, z);
  public static Matrix3d CreateScale(Vector3d s) => CreateScale(s.X, s.Y, s.Z);

  public static Matrix3d Mult(Matrix3d a, Matrix3d b) => a * b;
  public static Matrix3d operator *(Matrix3d a, Matrix3d b) => new(a.To4() * b.To4());
  public static Vector3d operator *(Vector3d v, Matrix3d m) => v.X * m.Row0 + v.Y * m.Row1 + v.Z * m.Row2;
  public static bool operator ==(Matrix3d a, Matrix3d b) => a.Equals(b);
  public static bool operator !=(Matrix3d a, Matrix3d b) => !a.Equals(b);

  public static Matrix3d Transpose(Matrix3d m) => new(Matrix4d.Transpose(m.To4()));
  public void Transpose() => this = Transpose(this);
  public readonly Matrix3d Transposed() => Transpose(this);
  /// <exception cref="InvalidOperationException">The matrix is singular.</exception>
  public static Matrix3d Invert(Matrix3d m) => new(Matrix4d.Invert(m.To4()));
  public void Invert() => this = Invert(this);
  /// <summary>The inverse, or (as in OpenTK 3) the matrix unchanged when its determinant is 0.</summary>
  public readonly Matrix3d Inverted() => Determinant == 0 ? this : Invert(this);

  public readonly bool Equals(Matrix3d other) => Row0 == other.Row0 && Row1 == other.Row1 && Row2 == other.Row2;
  public override readonly bool Equals(object? obj) => obj is Matrix3d m && Equals(m);
  public override readonly int GetHashCode() => HashCode.Combine(Row0, Row1, Row2);
  public override readonly string ToString() => string.Format(CultureInfo.CurrentCulture, "{0}\n{1}\n{2}", Row0, Row1, Row2);
}
