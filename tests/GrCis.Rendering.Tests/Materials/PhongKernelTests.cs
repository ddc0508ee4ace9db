using System;
using MathSupport;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Materials;

/// <summary>
/// The shading's Phong kernel (<c>PhongModel.ColorReflection</c> into a buffer, and <c>Directional</c> given the
/// normalized input) gives the bits of the model as GrCis defines it (the reference below: the same formula in one
/// piece, with its vectors by value), on random materials and directions: Schlick weights, total internal
/// reflection, refraction, ambient light, each component alone.
/// </summary>
public class PhongKernelTests
{
  // The Phong model in one piece, as it read before the kernel was split (the formula GrCis defines).
  static double[] Reference(PhongMaterial mat, Vector3d normal, Vector3d input, Vector3d output, ReflectionComponent comp)
  {
    int bands = mat.Color.Length;
    var result = new double[bands];
    bool viewOut = Vector3d.Dot(output, normal) > 0.0;
    if (input.X == 0.0 && input.Y == 0.0 && input.Z == 0.0)
    {
      double coef = viewOut ? mat.Ka : mat.Ka * mat.Kt;
      for (int i = 0; i < bands; i++)
        result[i] = coef * mat.Color[i];
      return result;
    }
    input.Normalize();
    double cosAlpha = Vector3d.Dot(input, normal);
    bool lightOut = cosAlpha > 0.0;
    double ks = mat.Ks, kd = mat.Kd, kt = mat.Kt;
    if (mat.Sch > 0.0)
    {
      double s = 1.0 - Math.Abs(cosAlpha);
      s = mat.Sch * s * s * s * s * s;
      ks += s * (kd + kt);
      kd *= 1.0 - s;
      kt *= 1.0 - s;
    }
    Vector3d r = Vector3d.Zero;
    double coefficient = 1.0;
    if (viewOut == lightOut)
    {
      if ((comp & ReflectionComponent.SPECULAR_REFLECTION) != 0)
      {
        r = 2.0 * cosAlpha * normal - input;
        if (!lightOut && -cosAlpha <= mat.cosTotal)
        {
          ks += kt;
          if (ks + kd > 1.0)
            ks = 1.0 - kd;
        }
      }
    }
    else if ((comp & ReflectionComponent.SPECULAR_REFRACTION) != 0)
    {
      r = Geometry.SpecularRefraction(normal, mat.n, input);
      coefficient = kt;
    }
    double diffuse = (comp & ReflectionComponent.DIFFUSE) != 0 ? coefficient * kd * Math.Abs(cosAlpha) : 0.0;
    double specular = 0.0;
    if (r.X != 0.0 || r.Y != 0.0 || r.Z != 0.0)
    {
      double cosBeta = Vector3d.Dot(r, output);
      if (cosBeta > 0.0)
        specular = coefficient * ks * Geometry.IntPow(cosBeta, mat.H);
    }
    for (int i = 0; i < bands; i++)
      result[i] = diffuse * mat.Color[i] + specular;
    return result;
  }

  static Vector3d RandomVector(Random r, double scale) =>
    new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5) * scale;

  static PhongMaterial RandomMaterial(Random r)
  {
    var color = new double[1 + r.Next(4)];
    for (int b = 0; b < color.Length; b++)
      color[b] = r.NextDouble();
    return new PhongMaterial(color, r.NextDouble() * 0.3, r.NextDouble(), r.NextDouble(), 1 + r.Next(200), r.Next(3) == 0 ? 0.0 : r.NextDouble())
    {
      Kt = r.Next(2) == 0 ? 0.0 : r.NextDouble(),
      n = 1.0 + r.NextDouble(),
    };
  }

  static void AssertBits(double[] expected, ReadOnlySpan<double> actual)
  {
    Assert.Equal(expected.Length, actual.Length);
    for (int b = 0; b < expected.Length; b++)
      Assert.Equal(BitConverter.DoubleToInt64Bits(expected[b]), BitConverter.DoubleToInt64Bits(actual[b]));
  }

  [Theory]
  [InlineData(1)]
  [InlineData(2)]
  public void The_kernel_gives_the_reference_bits_on_random_inputs(int seed)
  {
    var r = new Random(seed);
    ReflectionComponent[] comps = { ReflectionComponent.ALL, ReflectionComponent.SPECULAR_REFLECTION, ReflectionComponent.DIFFUSE,
                                    ReflectionComponent.SPECULAR_REFRACTION, ReflectionComponent.SPECULAR };
    Span<double> buffer = stackalloc double[8];
    for (int n = 0; n < 20000; n++)
    {
      PhongMaterial mat = RandomMaterial(r);
      Vector3d normal = RandomVector(r, 2.0).Normalized();
      // Inputs of all lengths (light vectors are not normalized), grazing ones, and the ambient zero vector.
      Vector3d input = n % 17 == 0 ? Vector3d.Zero : RandomVector(r, Math.Pow(10.0, 4.0 * r.NextDouble() - 2.0));
      if (n % 11 == 0)
        input -= Vector3d.Dot(input, normal) * normal * (1.0 - 1e-3 * r.NextDouble());
      Vector3d output = RandomVector(r, 1.0).Normalized();
      if (n % 5 == 0)
        output = Geometry.SpecularReflection(normal, input.Normalized());
      ReflectionComponent comp = comps[n % comps.Length];

      double[] expected = Reference(mat, normal, input, output, comp);
      Span<double> got = buffer[..mat.Color.Length];
      PhongModel.ColorReflection(mat, normal, input, output, comp, got);
      AssertBits(expected, got);
      AssertBits(expected, new PhongModel().ColorReflection(mat, normal, input, output, comp)!);
      if (input.X != 0.0 || input.Y != 0.0 || input.Z != 0.0)
      {
        got.Clear();
        PhongModel.Directional(mat, normal, input.Normalized(), output, comp, got);
        AssertBits(expected, got);
      }
    }
  }

  [Fact]
  public void Refraction_from_a_normalized_input_equals_the_general_form_bit_for_bit()
  {
    var r = new Random(7);
    for (int n = 0; n < 20000; n++)
    {
      Vector3d normal = RandomVector(r, Math.Pow(10.0, 2.0 * r.NextDouble() - 1.0));
      Vector3d input = RandomVector(r, Math.Pow(10.0, 4.0 * r.NextDouble() - 2.0));
      double index = 0.5 + 2.0 * r.NextDouble();
      Vector3d expected = Geometry.SpecularRefraction(normal, index, input);
      Vector3d got = Geometry.SpecularRefractionUnit(normal, index, input.Normalized());
      Assert.Equal(BitConverter.DoubleToInt64Bits(expected.X), BitConverter.DoubleToInt64Bits(got.X));
      Assert.Equal(BitConverter.DoubleToInt64Bits(expected.Y), BitConverter.DoubleToInt64Bits(got.Y));
      Assert.Equal(BitConverter.DoubleToInt64Bits(expected.Z), BitConverter.DoubleToInt64Bits(got.Z));
    }
  }
}
