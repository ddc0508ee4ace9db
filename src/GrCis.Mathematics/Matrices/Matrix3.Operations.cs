using System;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of the float Matrix3: columns, indexer, out-parameter creators, decomposition.
public partial struct Matrix3
{
  /// <summary>Column 0: the X of every row (read-only).</summary>
  public readonly Vector3 Column0 => new(Row0.X, Row1.X, Row2.X);
  /// <summary>Column 1: the Y of every row (read-only).</summary>
  public readonly Vector3 Column1 => new(Row0.Y, Row1.Y, Row2.Y);
  /// <summary>Column 2: the Z of every row (read-only).</summary>
  public readonly Vector3 Column2 => new(Row0.Z, Row1.Z, Row2.Z);
  /// <summary>The main diagonal (M11, M22, …); setting writes it back, leaving the other elements.</summary>
  public Vector3 Diagonal { readonly get => new(Row0.X, Row1.Y, Row2.Z); set { Row0.X = value.X; Row1.Y = value.Y; Row2.Z = value.Z; } }
  /// <summary>The trace: the sum of the diagonal elements.</summary>
  public readonly float Trace => Row0.X + Row1.Y + Row2.Z;

  /// <summary>The element in row <paramref name="rowIndex"/>, column <paramref name="columnIndex"/> (both 0..2); other
  /// indices throw <see cref="System.IndexOutOfRangeException"/>.</summary>
  public float this[int rowIndex, int columnIndex]
  {
    readonly get => rowIndex switch
    {
      0 => Row0[columnIndex], 1 => Row1[columnIndex], 2 => Row2[columnIndex],
      _ => throw new IndexOutOfRangeException($"Matrix3 row {rowIndex} is outside 0..2."),
    };
    set
    {
      switch (rowIndex)
      {
        case 0: Row0[columnIndex] = value; break;
        case 1: Row1[columnIndex] = value; break;
        case 2: Row2[columnIndex] = value; break;
        default: throw new IndexOutOfRangeException($"Matrix3 row {rowIndex} is outside 0..2.");
      }
    }
  }

  /// <summary>OpenTK's "normalisation": every element divided by the determinant.</summary>
  public void Normalize()
  {
    float d = Determinant;
    Row0 /= d; Row1 /= d; Row2 /= d;
  }

  /// <summary>A copy with every element divided by the determinant (OpenTK's "normalisation", see
  /// <see cref="Normalize()"/>).</summary>
  public readonly Matrix3 Normalized() { Matrix3 m = this; m.Normalize(); return m; }
  /// <summary>Each row made unit length: the rotation without the scale (a zero row becomes NaN).</summary>
  public readonly Matrix3 ClearScale() => new(Row0.Normalized(), Row1.Normalized(), Row2.Normalized());
  /// <summary>The scale alone: a diagonal matrix of the rows' lengths.</summary>
  public readonly Matrix3 ClearRotation() => CreateScale(Row0.Length, Row1.Length, Row2.Length);
  /// <summary>The scale along each axis: the lengths of the three rows.</summary>
  public readonly Vector3 ExtractScale() => new(Row0.Length, Row1.Length, Row2.Length);

  /// <summary>The rotation as a quaternion; <paramref name="row_normalise"/> first removes a scale of the rows.</summary>
  public readonly Quaternion ExtractRotation(bool row_normalise = true) => (Quaternion)((Matrix3d)this).ExtractRotation(row_normalise);

  /// <summary>The rotation of <paramref name="q"/> for row vectors; q need not be unit length.</summary>
  public static Matrix3 CreateFromQuaternion(Quaternion q) => new(Matrix4.CreateFromQuaternion(q));

  /// <summary><see cref="CreateFromAxisAngle(Vector3, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromAxisAngle(Vector3 axis, float angle, out Matrix3 result) => result = CreateFromAxisAngle(axis, angle);
  /// <summary><see cref="CreateFromQuaternion(Quaternion)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateFromQuaternion(in Quaternion q, out Matrix3 result) => result = CreateFromQuaternion(q);
  /// <summary><see cref="CreateRotationX(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationX(float angle, out Matrix3 result) => result = CreateRotationX(angle);
  /// <summary><see cref="CreateRotationY(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationY(float angle, out Matrix3 result) => result = CreateRotationY(angle);
  /// <summary><see cref="CreateRotationZ(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateRotationZ(float angle, out Matrix3 result) => result = CreateRotationZ(angle);
  /// <summary><see cref="CreateScale(float)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(float scale, out Matrix3 result) => result = CreateScale(scale);
  /// <summary><see cref="CreateScale(Vector3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void CreateScale(in Vector3 scale, out Matrix3 result) => result = CreateScale(scale);
  /// <summary><see cref="CreateScale(float, float, float)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateScale(float x, float y, float z, out Matrix3 result) => result = CreateScale(x, y, z);

  /// <summary>The sum, element by element.</summary>
  public static Matrix3 Add(Matrix3 left, Matrix3 right) => new(left.Row0 + right.Row0, left.Row1 + right.Row1, left.Row2 + right.Row2);
  /// <summary><see cref="Add(Matrix3, Matrix3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Add(in Matrix3 left, in Matrix3 right, out Matrix3 result) => result = Add(left, right);
  /// <summary><see cref="Mult(Matrix3, Matrix3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Mult(in Matrix3 left, in Matrix3 right, out Matrix3 result) => result = left * right;
  /// <summary><see cref="Invert(Matrix3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Matrix3 mat, out Matrix3 result) => result = Invert(mat);
  /// <summary><see cref="Transpose(Matrix3)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Transpose(in Matrix3 mat, out Matrix3 result) => result = Transpose(mat);
}
