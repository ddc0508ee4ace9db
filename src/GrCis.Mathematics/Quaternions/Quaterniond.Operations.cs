using System;

namespace OpenTK.Mathematics;

// OpenTK 3's remaining members of Quaterniond: Euler-angle and matrix constructors, ref/out twins.
public partial struct Quaterniond
{
  /// <summary>From Euler angles in radians (X, Y, Z), as <see cref="Quaterniond(double, double, double)"/>.</summary>
  public Quaterniond(Vector3d eulerAngles) : this(eulerAngles.X, eulerAngles.Y, eulerAngles.Z)
  {
  }

  /// <summary>Every component multiplied by the scalar.</summary>
  public static Quaterniond Multiply(Quaterniond quaternion, double scale) => quaternion * scale;
  /// <summary><see cref="Multiply(Quaterniond, double)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Quaterniond quaternion, double scale, out Quaterniond result) => result = quaternion * scale;
  /// <summary><see cref="Multiply(Quaterniond, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Multiply(in Quaterniond left, in Quaterniond right, out Quaterniond result) => result = left * right;
  /// <summary><see cref="Add(Quaterniond, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Add(in Quaterniond left, in Quaterniond right, out Quaterniond result) => result = left + right;
  /// <summary><see cref="Sub(Quaterniond, Quaterniond)"/>, with the result written to
  /// <paramref name="result"/>.</summary>
  public static void Sub(in Quaterniond left, in Quaterniond right, out Quaterniond result) => result = left - right;
  /// <summary><see cref="Conjugate(Quaterniond)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Conjugate(in Quaterniond q, out Quaterniond result) => result = Conjugate(q);
  /// <summary><see cref="Invert(Quaterniond)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Invert(in Quaterniond q, out Quaterniond result) => result = q.Inverted();
  /// <summary><see cref="Normalize(Quaterniond)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void Normalize(in Quaterniond q, out Quaterniond result) => result = q.Normalized();

  /// <summary>
  /// OpenTK 3's ref form of the Euler angles (X pitch, Y yaw, Z roll) builds <c>qY(yaw) · qZ(pitch) · qX(roll)</c>,
  /// not the constructor's order; kept as OpenTK 3 has it.
  /// </summary>
  public static void FromEulerAngles(in Vector3d eulerAngles, out Quaterniond result)
  {
    double cp = Math.Cos(0.5 * eulerAngles.X), sp = Math.Sin(0.5 * eulerAngles.X);
    double cy = Math.Cos(0.5 * eulerAngles.Y), sy = Math.Sin(0.5 * eulerAngles.Y);
    double cr = Math.Cos(0.5 * eulerAngles.Z), sr = Math.Sin(0.5 * eulerAngles.Z);
    result.W = cy * cp * cr - sy * sp * sr;
    result.X = sy * sp * cr + cy * cp * sr;
    result.Y = sy * cp * cr + cy * sp * sr;
    result.Z = cy * sp * cr - sy * cp * sr;
  }

  /// <summary>The rotation of an orthonormal matrix (row vectors, as <see cref="Matrix3d.CreateFromQuaternion(Quaterniond)"/> builds).</summary>
  public static Quaterniond FromMatrix(Matrix3d m)
  {
    // Shepperd's method: start from the largest of w, x, y, z so the square root is well away from zero.
    double trace = m.M11 + m.M22 + m.M33;
    if (trace > 0)
    {
      double s = 2.0 * Math.Sqrt(1.0 + trace);
      return new Quaterniond((m.M23 - m.M32) / s, (m.M31 - m.M13) / s, (m.M12 - m.M21) / s, 0.25 * s);
    }
    if (m.M11 > m.M22 && m.M11 > m.M33)
    {
      double s = 2.0 * Math.Sqrt(1.0 + m.M11 - m.M22 - m.M33);
      return new Quaterniond(0.25 * s, (m.M12 + m.M21) / s, (m.M13 + m.M31) / s, (m.M23 - m.M32) / s);
    }
    if (m.M22 > m.M33)
    {
      double s = 2.0 * Math.Sqrt(1.0 + m.M22 - m.M11 - m.M33);
      return new Quaterniond((m.M12 + m.M21) / s, 0.25 * s, (m.M23 + m.M32) / s, (m.M31 - m.M13) / s);
    }
    double t = 2.0 * Math.Sqrt(1.0 + m.M33 - m.M11 - m.M22);
    return new Quaterniond((m.M13 + m.M31) / t, (m.M23 + m.M32) / t, 0.25 * t, (m.M12 - m.M21) / t);
  }

  /// <summary><see cref="FromMatrix(Matrix3d)"/>, with the result written to <paramref name="result"/>.</summary>
  public static void FromMatrix(in Matrix3d matrix, out Quaterniond result) => result = FromMatrix(matrix);
}
