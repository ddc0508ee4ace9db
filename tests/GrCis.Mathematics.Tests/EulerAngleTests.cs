using System;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>
/// The Euler-angle quaternions against OpenTK 3.3.3's formulas, written out here from its sources as half-angle
/// products: the double constructor, the double ref form (a different order) and the float constructor.
/// </summary>
public class EulerAngleTests
{
  /// <summary>(cos, sin) of half of each angle.</summary>
  static (double C, double S) Half(double angle) => (Math.Cos(angle / 2), Math.Sin(angle / 2));

  // OpenTK 3.3.3 Quaterniond(pitch, yaw, roll): with (c1, s1) of yaw, (c2, s2) of pitch, (c3, s3) of roll,
  // w = c1c2c3 − s1s2s3, x = s1s2c3 + c1c2s3, y = s1c2c3 − c1s2s3, z = c1s2c3 + s1c2s3.
  static Quaterniond OpenTkConstructor(double pitch, double yaw, double roll)
  {
    var (c1, s1) = Half(yaw);
    var (c2, s2) = Half(pitch);
    var (c3, s3) = Half(roll);
    return new Quaterniond(s1 * s2 * c3 + c1 * c2 * s3, s1 * c2 * c3 - c1 * s2 * s3, c1 * s2 * c3 + s1 * c2 * s3, c1 * c2 * c3 - s1 * s2 * s3);
  }

  // OpenTK 3.3.3 Quaterniond.FromEulerAngles(ref Vector3d, out): the same products with the signs of y's and z's
  // second terms swapped.
  static Quaterniond OpenTkRefForm(double pitch, double yaw, double roll)
  {
    var (c1, s1) = Half(yaw);
    var (c2, s2) = Half(pitch);
    var (c3, s3) = Half(roll);
    return new Quaterniond(s1 * s2 * c3 + c1 * c2 * s3, s1 * c2 * c3 + c1 * s2 * s3, c1 * s2 * c3 - s1 * c2 * s3, c1 * c2 * c3 - s1 * s2 * s3);
  }

  // OpenTK 3.3.3 Quaternion(rotationX, rotationY, rotationZ), float: (c1, s1) of x, (c2, s2) of y, (c3, s3) of z,
  // w = c1c2c3 − s1s2s3, x = s1c2c3 + c1s2s3, y = c1s2c3 − s1c2s3, z = c1c2s3 + s1s2c3.
  static Quaternion OpenTkFloat(float x, float y, float z)
  {
    float c1 = (float)Math.Cos(x * 0.5f), s1 = (float)Math.Sin(x * 0.5f);
    float c2 = (float)Math.Cos(y * 0.5f), s2 = (float)Math.Sin(y * 0.5f);
    float c3 = (float)Math.Cos(z * 0.5f), s3 = (float)Math.Sin(z * 0.5f);
    return new Quaternion(s1 * c2 * c3 + c1 * s2 * s3, c1 * s2 * c3 - s1 * c2 * s3, c1 * c2 * s3 + s1 * s2 * c3, c1 * c2 * c3 - s1 * s2 * s3);
  }

  static void Near(Quaterniond expected, Quaterniond actual, double eps = 1e-15)
  {
    double d = Math.Max(Math.Max(Math.Abs(expected.X - actual.X), Math.Abs(expected.Y - actual.Y)), Math.Max(Math.Abs(expected.Z - actual.Z), Math.Abs(expected.W - actual.W)));
    Assert.True(d <= eps, $"{expected} != {actual}");
  }

  static Quaterniond Axis(Vector3d axis, double angle) => Quaterniond.FromAxisAngle(axis, angle);

  public static TheoryData<double, double, double> Angles => new()
  {
    { 0.3, -0.7, 1.1 }, { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 }, { -2.9, 1.3, 3.0 }, { Math.PI / 2, Math.PI / 3, -Math.PI / 4 },
  };

  [Fact]
  public void The_double_constructor_gives_OpenTKs_numbers()
  {
    // OpenTK 3.3.3's formula for pitch 0.3, yaw −0.7, roll 1.1, evaluated outside .NET.
    Quaterniond q = new(0.3, -0.7, 1.1);
    Near(new Quaterniond(0.44179967222724359, -0.36242009435522565, -0.057539988180335414, 0.81862926565549576), q, 1e-15);
    Vector3d angles = new(0.3, -0.7, 1.1);
    Quaterniond.FromEulerAngles(ref angles, out Quaterniond viaRef);
    Near(new Quaterniond(0.44179967222724359, -0.21567241009038501, 0.29689154005806329, 0.81862926565549576), viaRef, 1e-15);
  }

  [Theory]
  [MemberData(nameof(Angles))]
  public void The_double_constructor_and_its_twins_follow_OpenTKs_formula(double pitch, double yaw, double roll)
  {
    Quaterniond expected = OpenTkConstructor(pitch, yaw, roll);
    Assert.Equal(expected, new Quaterniond(pitch, yaw, roll));   // the same operations: bit for bit
    Assert.Equal(expected, new Quaterniond(new Vector3d(pitch, yaw, roll)));
    Assert.Equal(expected, Quaterniond.FromEulerAngles(pitch, yaw, roll));
    Assert.Equal(expected, Quaterniond.FromEulerAngles(new Vector3d(pitch, yaw, roll)));
    // As rotations: roll about X, yaw about Y, pitch about Z, multiplied in that order.
    Near(Axis(Vector3d.UnitX, roll) * Axis(Vector3d.UnitY, yaw) * Axis(Vector3d.UnitZ, pitch), expected, 1e-14);
  }

  [Theory]
  [MemberData(nameof(Angles))]
  public void The_double_ref_form_follows_OpenTKs_other_formula(double pitch, double yaw, double roll)
  {
    Vector3d angles = new(pitch, yaw, roll);
    Quaterniond.FromEulerAngles(ref angles, out Quaterniond q);
    Assert.Equal(OpenTkRefForm(pitch, yaw, roll), q);
    Near(Axis(Vector3d.UnitY, yaw) * Axis(Vector3d.UnitZ, pitch) * Axis(Vector3d.UnitX, roll), q, 1e-14);
  }

  [Theory]
  [MemberData(nameof(Angles))]
  public void The_float_constructor_and_its_twins_follow_OpenTKs_float_formula(double x, double y, double z)
  {
    (float fx, float fy, float fz) = ((float)x, (float)y, (float)z);
    Quaternion expected = OpenTkFloat(fx, fy, fz);
    Vector3 angles = new(fx, fy, fz);
    Quaternion.FromEulerAngles(ref angles, out Quaternion viaRef);
    foreach (Quaternion q in new[] { new Quaternion(fx, fy, fz), new Quaternion(angles), Quaternion.FromEulerAngles(fx, fy, fz), Quaternion.FromEulerAngles(angles), viaRef })
      Assert.Equal(expected, q);
    Quaterniond product = Axis(Vector3d.UnitX, fx) * Axis(Vector3d.UnitY, fy) * Axis(Vector3d.UnitZ, fz);
    Near(product, expected, 1e-6);
  }

  [Fact]
  public void The_float_and_double_constructors_differ_as_OpenTKs_did()
  {
    // The same three numbers: the float type turns about X, Y, Z by them; the double one reads them as pitch (Z), yaw (Y), roll (X).
    Quaterniond d = new(0.3, -0.7, 1.1);
    Quaternion f = new(0.3f, -0.7f, 1.1f);
    Assert.True(Math.Abs(d.X - f.X) > 0.1, $"{d} vs {f}");
    Near(new Quaterniond(-0.0575399882, -0.362420094, 0.441799672, 0.818629266), f, 1e-7);
  }
}
