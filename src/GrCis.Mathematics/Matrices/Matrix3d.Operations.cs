using System;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Matrix3d: columns, indexer, out-parameter creators, decomposition.
public partial struct Matrix3d
{
  public readonly Vector3d Column0 => new(Row0.X, Row1.X, Row2.X);
  public readonly Vector3d Column1 => new(Row0.Y, Row1.Y, Row2.Y);
  public readonly Vector3d Column2 => new(Row0.Z, Row1.Z, Row2.Z);
  public Vector3d Diagonal { readonly get => new(Row0.X, Row1.Y, Row2.Z); set { Row0.X = value.X; Row1.Y = value.Y; Row2.Z = value.Z; } }
  public readonly double Trace => Row0.X + Row1.Y + Row2.Z;

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

  public readonly Matrix3d Normalized() { Matrix3d m = this; m.Normalize(); return m; }
  public readonly Matrix3d ClearScale() => new(Row0.Normalized(), Row1.Normalized(), Row2.Normalized());
  public readonly Matrix3d ClearRotation() => CreateScale(Row0.Length, Row1.Length, Row2.Length);
  public readonly Vector3d ExtractScale() => new(Row0.Length, Row1.Length, Row2.Length);

  /// <summary>The rotation as a quaternion; <paramref name="row_normalise"/> first removes a scale of the rows.</summary>
  public readonly Quaterniond ExtractRotation(bool row_normalise = true) =>
    Quaterniond.FromMatrix(row_normalise ? ClearScale() : this);

  public static void CreateFromAxisAngle(Vector3d axis, double angle, out Matrix3d result) => result = CreateFromAxisAngle(axis, angle);
  public static Matrix3d CreateFromQuaternion(Quaterniond q) => new(Matrix4d.CreateFromQuaternion(q));
  public static void CreateFromQuaternion(in Quaterniond q, out Matrix3d result) => result = CreateFromQuaternion(q);
  public static void CreateRotationX(double angle, out Matrix3d result) => result = CreateRotationX(angle);
  public static void CreateRotationY(double angle, out Matrix3d result) => result = CreateRotationY(angle);
  public static void CreateRotationZ(double angle, out Matrix3d result) => result = CreateRotationZ(angle);
  public static void CreateScale(double scale, out Matrix3d result) => result = CreateScale(scale);
  public static void CreateScale(in Vector3d scale, out Matrix3d result) => result = CreateScale(scale);
  public static void CreateScale(double x, double y, double z, out Matrix3d result) => result = CreateScale(x, y, z);

  public static Matrix3d Add(Matrix3d left, Matrix3d right) => new(left.Row0 + right.Row0, left.Row1 + right.Row1, left.Row2 + right.Row2);
  public static void Add(in Matrix3d left, in Matrix3d right, out Matrix3d result) => result = Add(left, right);
  public static void Mult(in Matrix3d left, in Matrix3d right, out Matrix3d result) => result = left * right;
  public static void Invert(in Matrix3d mat, out Matrix3d result) => result = Invert(mat);
  public static void Transpose(in Matrix3d mat, out Matrix3d result) => result = Transpose(mat);
}
