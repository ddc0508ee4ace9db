using System;

namespace OpenTK.Mathematics;

// OpenTK 3's views of a float Matrix4: columns, diagonal, trace, determinant, element indexer, and the
// decomposition helpers (translation in the last row, scale as the lengths of the first three rows).
public partial struct Matrix4
{
  /// <summary>Column 0: the X of every row; setting writes it back into the rows.</summary>
  public Vector4 Column0 { readonly get => new(Row0.X, Row1.X, Row2.X, Row3.X); set { Row0.X = value.X; Row1.X = value.Y; Row2.X = value.Z; Row3.X = value.W; } }
  /// <summary>Column 1: the Y of every row; setting writes it back into the rows.</summary>
  public Vector4 Column1 { readonly get => new(Row0.Y, Row1.Y, Row2.Y, Row3.Y); set { Row0.Y = value.X; Row1.Y = value.Y; Row2.Y = value.Z; Row3.Y = value.W; } }
  /// <summary>Column 2: the Z of every row; setting writes it back into the rows.</summary>
  public Vector4 Column2 { readonly get => new(Row0.Z, Row1.Z, Row2.Z, Row3.Z); set { Row0.Z = value.X; Row1.Z = value.Y; Row2.Z = value.Z; Row3.Z = value.W; } }
  /// <summary>Column 3: the W of every row (the projective part under row vectors); setting writes it back into the
  /// rows.</summary>
  public Vector4 Column3 { readonly get => new(Row0.W, Row1.W, Row2.W, Row3.W); set { Row0.W = value.X; Row1.W = value.Y; Row2.W = value.Z; Row3.W = value.W; } }
  /// <summary>The main diagonal (M11, M22, …); setting writes it back, leaving the other elements.</summary>
  public Vector4 Diagonal { readonly get => new(Row0.X, Row1.Y, Row2.Z, Row3.W); set { Row0.X = value.X; Row1.Y = value.Y; Row2.Z = value.Z; Row3.W = value.W; } }
  /// <summary>The trace: the sum of the diagonal elements.</summary>
  public readonly float Trace => Row0.X + Row1.Y + Row2.Z + Row3.W;
  /// <summary>The determinant as OpenTK 3 sums it: 24 products of four elements, in float, left to right.</summary>
  public readonly float Determinant
  {
    get
    {
      float a = Row0.X, b = Row0.Y, c = Row0.Z, d = Row0.W, e = Row1.X, f = Row1.Y, g = Row1.Z, h = Row1.W;
      float i = Row2.X, j = Row2.Y, k = Row2.Z, l = Row2.W, m = Row3.X, n = Row3.Y, o = Row3.Z, p = Row3.W;
      return a * f * k * p - a * f * l * o + a * g * l * n - a * g * j * p
        + a * h * j * o - a * h * k * n - b * g * l * m + b * g * i * p
        - b * h * i * o + b * h * k * m - b * e * k * p + b * e * l * o
        + c * h * i * n - c * h * j * m + c * e * j * p - c * e * l * n
        + c * f * l * m - c * f * i * p - d * e * j * o + d * e * k * n
        - d * f * k * m + d * f * i * o - d * g * i * n + d * g * j * m;
    }
  }

  /// <summary>The element in row <paramref name="row"/>, column <paramref name="column"/> (both 0..3).</summary>
  public float this[int row, int column]
  {
    readonly get => row switch
    {
      0 => Row0[column], 1 => Row1[column], 2 => Row2[column], 3 => Row3[column],
      _ => throw new IndexOutOfRangeException($"Matrix4 row {row} is outside 0..3."),
    };
    set
    {
      switch (row)
      {
        case 0: Row0[column] = value; break;
        case 1: Row1[column] = value; break;
        case 2: Row2[column] = value; break;
        case 3: Row3[column] = value; break;
        default: throw new IndexOutOfRangeException($"Matrix4 row {row} is outside 0..3.");
      }
    }
  }

  /// <summary>OpenTK's "normalisation": every element divided by the determinant.</summary>
  public void Normalize()
  {
    float d = Determinant;
    Row0 /= d; Row1 /= d; Row2 /= d; Row3 /= d;
  }

  /// <summary>A copy with every element divided by the determinant (OpenTK's "normalisation", see
  /// <see cref="Normalize()"/>).</summary>
  public readonly Matrix4 Normalized() { Matrix4 m = this; m.Normalize(); return m; }

  /// <summary>The translation: x, y, z of Row3.</summary>
  public readonly Vector3 ExtractTranslation() => Row3.Xyz;
  /// <summary>The scale along each axis: the lengths of the x, y, z parts of the first three rows.</summary>
  public readonly Vector3 ExtractScale() => new(Row0.Xyz.Length, Row1.Xyz.Length, Row2.Xyz.Length);
  /// <summary>The last column (the projective part under row vectors).</summary>
  public readonly Vector4 ExtractProjection() => Column3;

  /// <summary>A copy with the translation (x, y, z of Row3) set to zero.</summary>
  public readonly Matrix4 ClearTranslation() { Matrix4 m = this; m.Row3.Xyz = Vector3.Zero; return m; }
  /// <summary>A copy with the last column (the projective part under row vectors) set to zero.</summary>
  public readonly Matrix4 ClearProjection() { Matrix4 m = this; m.Column3 = Vector4.Zero; return m; }

  /// <summary>Each of the first three rows made unit length: the rotation (and translation) without the scale.</summary>
  public readonly Matrix4 ClearScale()
  {
    Matrix4 m = this;
    m.Row0.Xyz = Row0.Xyz.Normalized();
    m.Row1.Xyz = Row1.Xyz.Normalized();
    m.Row2.Xyz = Row2.Xyz.Normalized();
    return m;
  }

  /// <summary>Keeps each axis's length but drops its direction (a pure scale in the upper 3×3).</summary>
  public readonly Matrix4 ClearRotation()
  {
    Matrix4 m = this;
    m.Row0.Xyz = new Vector3(Row0.Xyz.Length, 0, 0);
    m.Row1.Xyz = new Vector3(0, Row1.Xyz.Length, 0);
    m.Row2.Xyz = new Vector3(0, 0, Row2.Xyz.Length);
    return m;
  }

  /// <summary>The rotation of the upper 3×3 part; <paramref name="row_normalise"/> first removes a scale.</summary>
  public readonly Quaternion ExtractRotation(bool row_normalise = true) => (Quaternion)((Matrix4d)this).ExtractRotation(row_normalise);
}
