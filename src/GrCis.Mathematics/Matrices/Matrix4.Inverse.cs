using System;

namespace OpenTK.Mathematics;

// The float inverse: the adjugate by cofactors divided by the determinant, every cofactor a signed sum of six
// triple products in OpenTK 3's order, so results (ill-conditioned matrices included) are OpenTK's to the bit.
public partial struct Matrix4
{
  // p1 − p2 − p3 + p4 + p5 − p6, left to right; a cofactor with the opposite signs is its exact negation.
  static float Six(float p1, float p2, float p3, float p4, float p5, float p6) => p1 - p2 - p3 + p4 + p5 - p6;

  static Matrix4 Inverse(in Matrix4 mat)
  {
    // m[r * 4 + c] is row r, column c.
    float m0 = mat.Row0.X, m1 = mat.Row0.Y, m2 = mat.Row0.Z, m3 = mat.Row0.W;
    float m4 = mat.Row1.X, m5 = mat.Row1.Y, m6 = mat.Row1.Z, m7 = mat.Row1.W;
    float m8 = mat.Row2.X, m9 = mat.Row2.Y, m10 = mat.Row2.Z, m11 = mat.Row2.W;
    float m12 = mat.Row3.X, m13 = mat.Row3.Y, m14 = mat.Row3.Z, m15 = mat.Row3.W;

    float i0 = Six(m5 * m10 * m15, m5 * m11 * m14, m9 * m6 * m15, m9 * m7 * m14, m13 * m6 * m11, m13 * m7 * m10);
    float i4 = -Six(m4 * m10 * m15, m4 * m11 * m14, m8 * m6 * m15, m8 * m7 * m14, m12 * m6 * m11, m12 * m7 * m10);
    float i8 = Six(m4 * m9 * m15, m4 * m11 * m13, m8 * m5 * m15, m8 * m7 * m13, m12 * m5 * m11, m12 * m7 * m9);
    float i12 = -Six(m4 * m9 * m14, m4 * m10 * m13, m8 * m5 * m14, m8 * m6 * m13, m12 * m5 * m10, m12 * m6 * m9);
    float i1 = -Six(m1 * m10 * m15, m1 * m11 * m14, m9 * m2 * m15, m9 * m3 * m14, m13 * m2 * m11, m13 * m3 * m10);
    float i5 = Six(m0 * m10 * m15, m0 * m11 * m14, m8 * m2 * m15, m8 * m3 * m14, m12 * m2 * m11, m12 * m3 * m10);
    float i9 = -Six(m0 * m9 * m15, m0 * m11 * m13, m8 * m1 * m15, m8 * m3 * m13, m12 * m1 * m11, m12 * m3 * m9);
    float i13 = Six(m0 * m9 * m14, m0 * m10 * m13, m8 * m1 * m14, m8 * m2 * m13, m12 * m1 * m10, m12 * m2 * m9);
    float i2 = Six(m1 * m6 * m15, m1 * m7 * m14, m5 * m2 * m15, m5 * m3 * m14, m13 * m2 * m7, m13 * m3 * m6);
    float i6 = -Six(m0 * m6 * m15, m0 * m7 * m14, m4 * m2 * m15, m4 * m3 * m14, m12 * m2 * m7, m12 * m3 * m6);
    float i10 = Six(m0 * m5 * m15, m0 * m7 * m13, m4 * m1 * m15, m4 * m3 * m13, m12 * m1 * m7, m12 * m3 * m5);
    float i14 = -Six(m0 * m5 * m14, m0 * m6 * m13, m4 * m1 * m14, m4 * m2 * m13, m12 * m1 * m6, m12 * m2 * m5);
    float i3 = -Six(m1 * m6 * m11, m1 * m7 * m10, m5 * m2 * m11, m5 * m3 * m10, m9 * m2 * m7, m9 * m3 * m6);
    float i7 = Six(m0 * m6 * m11, m0 * m7 * m10, m4 * m2 * m11, m4 * m3 * m10, m8 * m2 * m7, m8 * m3 * m6);
    float i11 = -Six(m0 * m5 * m11, m0 * m7 * m9, m4 * m1 * m11, m4 * m3 * m9, m8 * m1 * m7, m8 * m3 * m5);
    float i15 = Six(m0 * m5 * m10, m0 * m6 * m9, m4 * m1 * m10, m4 * m2 * m9, m8 * m1 * m6, m8 * m2 * m5);

    float det = m0 * i0 + m1 * i4 + m2 * i8 + m3 * i12;
    if (det == 0) throw new InvalidOperationException("Matrix4 is singular and cannot be inverted.");
    float s = 1f / det;
    return new Matrix4(i0 * s, i1 * s, i2 * s, i3 * s, i4 * s, i5 * s, i6 * s, i7 * s,
                       i8 * s, i9 * s, i10 * s, i11 * s, i12 * s, i13 * s, i14 * s, i15 * s);
  }
}
