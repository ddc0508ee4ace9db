using System;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Materials;

public class PhongModelTests
{
  static readonly Vector3d N = Vector3d.UnitZ;

  [Fact]
  public void Ambient_light_gives_ka_times_colour()
  {
    var m = new PhongMaterial(new double[] { 0.5, 1, 0 }, 0.2, 0.6, 0.3, 16, 0.0);
    double[] r = new PhongModel().ColorReflection(m, N, Vector3d.Zero, N, ReflectionComponent.ALL)!;
    Assert.Equal(new[] { 0.1, 0.2, 0.0 }, r);
  }

  [Fact]
  public void Pure_phong_head_on_light_and_viewer_is_kd_plus_ks()
  {
    var m = new PhongMaterial(new double[] { 1, 1, 1 }, 0.2, 0.6, 0.3, 16, 0.0);
    double[] r = new PhongModel().ColorReflection(m, N, new Vector3d(0, 0, 5), N, ReflectionComponent.ALL)!;
    Assert.Equal(0.9, r[0], 12);
  }

  [Fact]
  public void Specular_highlight_falls_off_with_the_exponent()
  {
    var m = new PhongMaterial(new double[] { 0, 0, 0 }, 0, 0, 1, 10, 0.0);
    Vector3d light = new(1, 0, 1);   // 45° from the normal
    Vector3d viewer = new Vector3d(-1, 0, 1).Normalized();   // exactly the mirror direction
    Assert.Equal(1.0, new PhongModel().ColorReflection(m, N, light, viewer, ReflectionComponent.ALL)![0], 12);
    Assert.Equal(System.Math.Pow(System.Math.Cos(0.2), 10),
      new PhongModel().ColorReflection(m, N, light, new Vector3d(-System.Math.Sin(System.Math.PI / 4 + 0.2), 0, System.Math.Cos(System.Math.PI / 4 + 0.2)), ReflectionComponent.ALL)![0], 10);
  }

  [Fact]
  public void Schlick_adds_specular_at_grazing_light()
  {
    var plain = new PhongMaterial(new double[] { 1, 1, 1 }, 0, 0.5, 0.5, 1, 0.0);
    var schlick = new PhongMaterial(new double[] { 1, 1, 1 }, 0, 0.5, 0.5, 1, 1.0);
    Vector3d light = new(1, 0, 0.05), viewer = new Vector3d(-1, 0, 0.05).Normalized();
    double a = new PhongModel().ColorReflection(plain, N, light, viewer, ReflectionComponent.SPECULAR_REFLECTION)![0];
    double b = new PhongModel().ColorReflection(schlick, N, light, viewer, ReflectionComponent.SPECULAR_REFLECTION)![0];
    Assert.True(b > a + 0.3, $"Schlick {b} should exceed plain {a} at grazing angles");
  }

  [Fact]
  public void Opaque_surface_lit_from_behind_reflects_nothing()
  {
    var m = new PhongMaterial(new double[] { 1, 1, 1 }, 0.2, 0.6, 0.3, 16, 0.0);
    double[] r = new PhongModel().ColorReflection(m, N, new Vector3d(0, 0, -1), N, ReflectionComponent.ALL)!;
    Assert.Equal(0.0, r[0]);
  }

  [Fact]
  public void Refraction_bends_towards_the_normal_when_entering_denser_medium()
  {
    Vector3d toViewer = new Vector3d(1, 0, 1).Normalized();   // the ray came from +x,+z
    Vector3d t = MathSupport.Geometry.SpecularRefraction(N, 1.5, toViewer);
    // Snell: sin(out) = sin(45°) / 1.5, going down (-z) and on to -x.
    Assert.True(t.Z < 0 && t.X < 0);
    double sinOut = System.Math.Abs(t.X) / t.Length;
    Assert.Equal(System.Math.Sin(System.Math.PI / 4) / 1.5, sinOut, 12);
  }

  [Fact]
  public void Total_internal_reflection_returns_zero_vector()
  {
    Vector3d fromInside = new Vector3d(1, 0, -0.1).Normalized();   // grazing, on the back side
    Assert.Equal(Vector3d.Zero, MathSupport.Geometry.SpecularRefraction(N, 1.5, fromInside));
  }

  [Fact]
  public void Material_clone_is_deep()
  {
    var m = new PhongMaterial(new double[] { 1, 2, 3 }, 0.1, 0.2, 0.3, 4) { Kt = 0.5, n = 1.33 };
    var c = (PhongMaterial)m.Clone();
    c.Color[0] = 9;
    Assert.Equal(1, m.Color[0]);
    Assert.Equal(1.33, c.n);
    Assert.Equal(0.5, c.Kt);
    Assert.Equal(System.Math.Sqrt(1.33 * 1.33 - 1) / 1.33, c.cosTotal, 12);
  }

  [Fact]
  public void Scratch_copy_gives_each_index_its_own_critical_cosine_when_indices_alternate()
  {
    // The shading's scratch copy remembers the last index's cosTotal: switching glass, water, glass must not keep a stale one.
    var glass = new PhongMaterial { n = 1.5 };
    var water = new PhongMaterial { n = 1.33 };
    var air = new PhongMaterial { n = 1.0 };
    var scratch = new PhongMaterial();
    foreach (PhongMaterial m in new[] { glass, water, glass, glass, air, water })
    {
      scratch.CopyFrom(m, m.Color);
      Assert.Equal(m.n, scratch.n);
      Assert.Equal(BitConverter.DoubleToInt64Bits(m.cosTotal), BitConverter.DoubleToInt64Bits(scratch.cosTotal));
    }
  }

  [Fact]
  public void Int_pow_of_a_negative_exponent_is_the_reciprocal_power()
  {
    Assert.Equal(1.0 / (1.5 * 1.5 * 1.5), MathSupport.Geometry.IntPow(1.5, -3));
    Assert.Equal(1.0, MathSupport.Geometry.IntPow(0.3, 0));
    Assert.Equal(0.3 * 0.3 * 0.3 * 0.3 * 0.3, MathSupport.Geometry.IntPow(0.3, 5), 15);
  }
}
