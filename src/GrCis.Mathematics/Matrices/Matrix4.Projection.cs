using System;

namespace OpenTK.Mathematics;

// OpenTK 4's inverses of the projection creators (the parameters read back from such a matrix) and the row swizzles.
public partial struct Matrix4
{
  /// <summary>The parameters of <see cref="CreatePerspectiveOffCenter(float, float, float, float, float, float)"/> that made this matrix.</summary>
  public readonly void ExtractPerspectiveOffCenter(out float left, out float right, out float bottom, out float top, out float depthNear, out float depthFar)
  {
    // Row2.Z = −(f + n)/(f − n) and Row3.Z = −2fn/(f − n) give n and f; Row2.X = (r + l)/(r − l), Row0.X = 2n/(r − l).
    depthNear = Row3.Z / (Row2.Z - 1);
    depthFar = Row3.Z / (Row2.Z + 1);
    left = depthNear * (Row2.X - 1) / Row0.X;
    right = depthNear * (Row2.X + 1) / Row0.X;
    bottom = depthNear * (Row2.Y - 1) / Row1.Y;
    top = depthNear * (Row2.Y + 1) / Row1.Y;
  }

  /// <summary>The parameters of <see cref="CreatePerspectiveFieldOfView(float, float, float, float)"/> that made this matrix.</summary>
  public readonly void ExtractPerspectiveFieldOfView(out float fovy, out float aspect, out float depthNear, out float depthFar)
  {
    fovy = 2f * MathF.Atan(1 / Row1.Y);
    aspect = Row1.Y / Row0.X;
    depthNear = Row3.Z / (Row2.Z - 1);
    depthFar = Row3.Z / (Row2.Z + 1);
  }

  /// <summary>The parameters of <see cref="CreateOrthographicOffCenter(float, float, float, float, float, float)"/> that made this matrix.</summary>
  public readonly void ExtractOrthographicOffCenter(out float left, out float right, out float bottom, out float top, out float depthNear, out float depthFar)
  {
    left = -(1 + Row3.X) / Row0.X;
    right = (1 - Row3.X) / Row0.X;
    bottom = -(1 + Row3.Y) / Row1.Y;
    top = (1 - Row3.Y) / Row1.Y;
    depthNear = (1 + Row3.Z) / Row2.Z;
    depthFar = -(1 - Row3.Z) / Row2.Z;
  }

  /// <summary>The parameters of <see cref="CreateOrthographic(float, float, float, float)"/> that made this matrix.</summary>
  public readonly void ExtractOrthographic(out float width, out float height, out float depthNear, out float depthFar)
  {
    ExtractOrthographicOffCenter(out float left, out float right, out float bottom, out float top, out depthNear, out depthFar);
    width = right - left;
    height = top - bottom;
  }

  /// <summary>The matrix that, multiplied from the left, makes row i of the product row <c>rowForRow{i}</c> of the right operand.</summary>
  public static Matrix4 CreateSwizzle(int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3) =>
    Swizzle(Identity, rowForRow0, rowForRow1, rowForRow2, rowForRow3);
  /// <summary><see cref="CreateSwizzle(int, int, int, int)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void CreateSwizzle(int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3, out Matrix4 result) =>
    result = CreateSwizzle(rowForRow0, rowForRow1, rowForRow2, rowForRow3);

  /// <summary>A matrix whose row i is row <c>rowForRow{i}</c> of <paramref name="mat"/> (each 0..3).</summary>
  public static Matrix4 Swizzle(Matrix4 mat, int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3) =>
    new(mat.Row(rowForRow0), mat.Row(rowForRow1), mat.Row(rowForRow2), mat.Row(rowForRow3));
  /// <summary><see cref="Swizzle(Matrix4, int, int, int, int)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Swizzle(in Matrix4 mat, int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3, out Matrix4 result) =>
    result = Swizzle(mat, rowForRow0, rowForRow1, rowForRow2, rowForRow3);
  /// <summary>Reorders the rows in place, as <see cref="Swizzle(Matrix4, int, int, int, int)"/>.</summary>
  public void Swizzle(int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3) =>
    this = Swizzle(this, rowForRow0, rowForRow1, rowForRow2, rowForRow3);
  /// <summary>A copy with its rows reordered, as <see cref="Swizzle(Matrix4, int, int, int, int)"/>.</summary>
  public readonly Matrix4 Swizzled(int rowForRow0, int rowForRow1, int rowForRow2, int rowForRow3) =>
    Swizzle(this, rowForRow0, rowForRow1, rowForRow2, rowForRow3);

  readonly Vector4 Row(int i) => i switch
  {
    0 => Row0, 1 => Row1, 2 => Row2, 3 => Row3,
    _ => throw new IndexOutOfRangeException($"Matrix4 row {i} is outside 0..3."),
  };
}
