using System;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Matrix3d: columns, indexer, out-parameter creators, decomposition.
public partial struct Matrix3d
{
  /// <summary>Column 0: the X of every row (read-only).</summary>
  public readonly Vector3d Column0 => new(Row0.X, Row1.X, Row2.X);
  /// <summary>Column 1: the Y of every row (read-only).</summary>
  public readonly Vector3d Column1 => new(Row0.Y, Row1.Y, Row2.Y);
  /// <summary>Column 2: the Z of every row (read-only).</summary>
  public readonly Vector3d Column2 => new(Row0.Z, Row1.Z, Row2.Z);
  /// <summary>The main diagonal (M11, M22, …); setting writes it back, leaving the other elements.</summary>
  public Vector3d Diagonal { readonly get => new(Row0.X, Row1.Y, Row2.Z); set { Row0.X = value.X; Row1.Y = value.Y; Row2.Z = value.Z; } }
  /// <summary>The trace: the sum of the diagonal elements.</summary>
  public readonly double Trace => Row0.X + Row1.Y + Row2.Z;

  /// <summary>The element in row <paramref name="rowIndex"/>, column <paramref name="columnIndex"/> (both 0..2); other
  /// indices throw <see cref="System.IndexOutOfRangeException"/>.</summary>
  public double this[int rowIndex, int columnIndex]
  {
    readonly get => rowIndex switch
    {
      0 => Row0[columnIndex], 1 => Row1[columnIndex], 2 => Row2[columnIndex],
      _ => throw new IndexOutOfRangeException($"Matrix3d row {rowIndex} is outside 0..2."),
    };
    set
    {
      switch (rowIndex)
      {
        case 0: Row0[columnIndex] = value; break;
        case 1: Row1[columnIndex] = value; break;
        case 2: Row2[columnIndex] = value; break;
        default: throw new IndexOutOfRangeException($"Matrix3d row {rowIndex} is outside 0..2.");
      }
    }
  }

  /// <summary>OpenTK's "normalisation": every element divided by the determinant.</summary>
  public void Normalize()
  {
    double d = Determinant;
    Row0 /= d; Row1 /= d; Row2 /= d;
  }

  /// <summary>A copy with every element divided by the determinant (OpenTK's "normalisation", see
  /// <see cref="Normalize()"/>).</summary>
  public readonly Matrix3d Normalized() { Matrix3d m = this; m.Normalize(); return m; }
  /// <summary>Each row made unit length: the rotation without the scale (a zero row becomes NaN).</summary>
  public readonly Matrix3d ClearScale() => new(Row0.Normalized(), Row1.Normalized(), Row2.Normalized());
  /// <summary>The scale alone: a diagonal matrix of the rows' lengths.</summary>
  public readonly Matrix3d ClearRotation() => CreateScale(Row0.Length, Row1.Length, Row2.Length);
  /// <summary>The scale along each axis: the lengths of the three rows.</summary>
  public readonly Vector3d ExtractScale() => new(Row0.Length, Row1.Length, Row2.Length);

  /// <summary>The rotation as a quaternion; <paramref name="row_normalise"/> first removes a scale of the rows.</summary>
  public readonly Quaterniond ExtractRotation(bool row_normalise = true) =>
    Quaterniond.FromMatrix(row_normalise ? ClearScale() : this);

  /// <summary><see cref="CreateFromAxisAngle(Vector3d, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromAxisAngle(Vector3d axis, double angle, out Matrix3d result) => result = CreateFromAxisAngle(axis, angle);
  /// <summary>The rotation of the unit quaternion <paramref name="q"/>, built from its axis and angle
  /// (<see cref="Quaterniond.ToAxisAngle(out Vector3d, out double)"/>).</summary>
  public static Matrix3d CreateFromQuaternion(Quaterniond q) => new(Matrix4d.CreateFromQuaternion(q));
  /// <summary><see cref="CreateFromQuaternion(Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromQuaternion(in Quaterniond q, out Matrix3d result) => result = CreateFromQuaternion(q);
  /// <summary><see cref="CreateRotationX(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationX(double angle, out Matrix3d result) => result = CreateRotationX(angle);
  /// <summary><see cref="CreateRotationY(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationY(double angle, out Matrix3d result) => result = CreateRotationY(angle);
  /// <summary><see cref="CreateRotationZ(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationZ(double angle, out Matrix3d result) => result = CreateRotationZ(angle);
  /// <summary><see cref="CreateScale(double)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(double scale, out Matrix3d result) => result = CreateScale(scale);
  /// <summary><see cref="CreateScale(Vector3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(in Vector3d scale, out Matrix3d result) => result = CreateScale(scale);
  /// <summary><see cref="CreateScale(double, double, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateScale(double x, double y, double z, out Matrix3d result) => result = CreateScale(x, y, z);

  /// <summary>The sum, element by element.</summary>
  public static Matrix3d Add(Matrix3d left, Matrix3d right) => new(left.Row0 + right.Row0, left.Row1 + right.Row1, left.Row2 + right.Row2);
  /// <summary><see cref="Add(Matrix3d, Matrix3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Matrix3d left, in Matrix3d right, out Matrix3d result) => result = Add(left, right);
  /// <summary><see cref="Mult(Matrix3d, Matrix3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix3d left, in Matrix3d right, out Matrix3d result) => result = left * right;
  /// <summary><see cref="Invert(Matrix3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Matrix3d mat, out Matrix3d result) => result = Invert(mat);
  /// <summary><see cref="Transpose(Matrix3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Transpose(in Matrix3d mat, out Matrix3d result) => result = Transpose(mat);
}
