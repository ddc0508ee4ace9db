using System;

namespace OpenTK.Mathematics;

// OpenTK 4's way back from a quaternion to the angles of Quaternion(x, y, z) = qX(x) · qY(y) · qZ(z).
public partial struct Quaternion
{
  /// <summary>
  /// The angles (x, y, z) with <c>FromEulerAngles(result)</c> the same rotation, y within ±π/2. Near y = ±π/2 (gimbal lock)
  /// x is 0 and z takes the whole turn about the shared axis. A quaternion that is not unit length is read as its direction.
  /// </summary>
  public readonly Vector3 ToEulerAngles()
  {
    float ww = W * W, xx = X * X, yy = Y * Y, zz = Z * Z;
    float norm = ww + xx + yy + zz;
    float sinY = X * Z + W * Y; // half of sin y, times the squared norm
    const float pole = 0.4999995f;
    if (sinY > pole * norm)
      return new Vector3(0, MathHelper.PiOver2, 2 * MathF.Atan2(X, W));
    if (sinY < -pole * norm)
      return new Vector3(0, -MathHelper.PiOver2, -2 * MathF.Atan2(X, W));
    return new Vector3(
      MathF.Atan2(2 * (W * X - Y * Z), ww - xx - yy + zz),
      MathF.Asin(2 * sinY / norm),
      MathF.Atan2(2 * (W * Z - X * Y), ww + xx - yy - zz));
  }

  /// <summary><see cref="ToEulerAngles()"/>, written to <paramref name="angles"/>.</summary>
  public readonly void ToEulerAngles(out Vector3 angles) => angles = ToEulerAngles();
  /// <summary>The Euler angles of <paramref name="q"/>, as <see cref="ToEulerAngles()"/>, written to
  /// <paramref name="result"/>.</summary>
  public static void ToEulerAngles(in Quaternion q, out Vector3 result) => result = q.ToEulerAngles();
}
