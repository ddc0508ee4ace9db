using System;
using MathSupport;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The Phong reflectance model as GrCis defines it, with an optional Schlick weight that moves
/// energy from the diffuse and transmitted parts into the specular one at grazing angles.
/// </summary>
[Serializable]
public class PhongModel : IReflectanceModel
{
  /// <summary>A new default <see cref="PhongMaterial"/> (see <see cref="PhongMaterial()"/>).</summary>
  public IMaterial DefaultMaterial() => new PhongMaterial();

  /// <summary>Reflected colour at a completed hit: its <see cref="Intersection.Material"/> and <see cref="Intersection.Normal"/>.</summary>
  /// <param name="intersection">The completed hit.</param>
  /// <param name="input">From the surface point towards the light, any length; zero for ambient light.</param>
  /// <param name="output">Unit direction from the surface point towards the viewer.</param>
  /// <param name="comp">Which parts to compute (flags).</param>
  public double[]? ColorReflection(Intersection intersection, Vector3d input, Vector3d output, ReflectionComponent comp) =>
    ColorReflection(intersection.Material!, intersection.Normal, input, output, comp);

  /// <summary>
  /// Phong reflectance of a <see cref="PhongMaterial"/> (null for any other material), a new array of one value per band
  /// of the material's colour. Ambient light (zero <paramref name="input"/>) gives Ka·colour (Ka·Kt·colour seen from
  /// behind the surface). Otherwise Kd·|cos α|·colour plus the colourless highlight Ks·cos^H β, where β is measured from
  /// the mirrored light direction; when light and viewer are on opposite sides and <paramref name="comp"/> asks for
  /// <see cref="ReflectionComponent.SPECULAR_REFRACTION"/>, the highlight is about the refracted direction and both terms
  /// are weighted by Kt. With <see cref="PhongMaterial.Sch"/> &gt; 0, Schlick's term moves part of Kd and Kt into Ks
  /// at grazing angles; total internal reflection moves Kt into Ks.
  /// </summary>
  /// <param name="material">The surface material.</param>
  /// <param name="normal">Unit surface normal.</param>
  /// <param name="input">From the surface point towards the light, any length; zero for ambient light.</param>
  /// <param name="output">Unit direction from the surface point towards the viewer.</param>
  /// <param name="comp">Which parts to compute (flags).</param>
  public double[]? ColorReflection(IMaterial material, Vector3d normal, Vector3d input, Vector3d output, ReflectionComponent comp)
  {
    if (material is not PhongMaterial mat)
      return null;
    double[] result = new double[mat.Color.Length];
    ColorReflection(mat, normal, input, output, comp, result);
    return result;
  }

  /// <summary>
  /// The same computation into a caller's buffer of <c>mat.Color.Length</c> bands (the shading hot path
  /// uses it to avoid one array per light and hit).
  /// </summary>
  internal static void ColorReflection(PhongMaterial mat, in Vector3d normal, in Vector3d input, in Vector3d output, ReflectionComponent comp, Span<double> result) =>
    ColorReflection(mat, mat.Color, normal, input, output, comp, result);

  /// <summary>
  /// The same computation for <paramref name="mat"/>'s coefficients and the colour <paramref name="color"/> in place of
  /// <c>mat.Color</c> (the prepared kernel shades a hit's surface colour without a material copy per hit).
  /// </summary>
  internal static void ColorReflection(PhongMaterial mat, ReadOnlySpan<double> color, in Vector3d normal, in Vector3d input, in Vector3d output, ReflectionComponent comp, Span<double> result)
  {
    // Ambient light has no direction.
    if (input.X == 0.0 && input.Y == 0.0 && input.Z == 0.0)
      Ambient(mat, color, Vector3d.Dot(output, normal) > 0.0, result);
    else
      Directional(mat, color, normal, input.Normalized(), output, comp, result);
  }

  static void Ambient(PhongMaterial mat, ReadOnlySpan<double> color, bool viewOut, Span<double> result)
  {
    double coef = viewOut ? mat.Ka : mat.Ka * mat.Kt;
    result = result[..color.Length];
    for (int i = 0; i < result.Length; i++)
      result[i] = coef * color[i];
  }

  /// <summary>
  /// <see cref="ColorReflection(PhongMaterial, in Vector3d, in Vector3d, in Vector3d, ReflectionComponent, Span{double})"/>
  /// of a non-zero input, given normalized (by <see cref="Vector3d.Normalized"/>): a caller that already has that
  /// value (the shading's view direction) saves its square root and division.
  /// </summary>
  internal static void Directional(PhongMaterial mat, in Vector3d normal, in Vector3d unitInput, in Vector3d output, ReflectionComponent comp, Span<double> result) =>
    Directional(mat, mat.Color, normal, unitInput, output, comp, result);

  /// <summary><see cref="Directional(PhongMaterial, in Vector3d, in Vector3d, in Vector3d, ReflectionComponent, Span{double})"/> with <paramref name="color"/> in place of <c>mat.Color</c>.</summary>
  internal static void Directional(PhongMaterial mat, ReadOnlySpan<double> color, in Vector3d normal, in Vector3d unitInput, in Vector3d output, ReflectionComponent comp, Span<double> result)
  {
    bool viewOut = Vector3d.Dot(output, normal) > 0.0;
    Vector3d input = unitInput;
    double cosAlpha = Vector3d.Dot(input, normal);
    bool lightOut = cosAlpha > 0.0;
    double ks = mat.Ks, kd = mat.Kd, kt = mat.Kt;

    if (mat.Sch > 0.0)
    {
      // Schlick: more mirror at grazing angles, taken from diffuse and transmission.
      double u = Math.Abs(cosAlpha);
      double s = 1.0 - u;
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
          // Total internal reflection takes the transmitted energy.
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

    result = result[..color.Length];
    for (int i = 0; i < result.Length; i++)
      result[i] = diffuse * color[i] + specular;
  }
}
