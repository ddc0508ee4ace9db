using System;

namespace Rendering;

/// <summary>Phong material: ambient, diffuse and specular coefficients, shininess, transparency and index of refraction.</summary>
[Serializable]
public class PhongMaterial : IMaterial
{
  /// <inheritdoc/>
  public double[] Color { get; set; }

  /// <summary>Ambient coefficient.</summary>
  public double Ka { get; set; }

  /// <summary>Diffuse coefficient.</summary>
  public double Kd { get; set; }

  /// <summary>Specular coefficient (also the weight of the mirrored ray).</summary>
  public double Ks { get; set; }

  /// <summary>Specular exponent (shininess).</summary>
  public int H { get; set; }

  /// <summary>Transparency coefficient (0 = opaque, the default): the weight of the refracted ray and of the light passing through the surface.</summary>
  public double Kt { get; set; }

  /// <summary>Weight of Schlick's Fresnel approximation: 0 = pure Phong, 1 = full Schlick.</summary>
  public double Sch { get; set; }

  /// <summary>
  /// Radiance the surface emits (linear, per band), or null for none. Only <see cref="PathTracing"/> and
  /// <see cref="RayTracing"/>'s successors that light a scene by its surfaces read it; Whitted ray tracing ignores it.
  /// The emission is one-sided: it leaves the side the surface normal points to.
  /// </summary>
  public double[]? Emission { get; set; }

  /// <summary>Cosine of the critical angle for total internal reflection (0 when n ≤ 1).</summary>
  public double cosTotal;

  double refraction;

  /// <summary>GrCis's backing name of <see cref="n"/>, for subclasses.</summary>
  protected double _n
  {
    get => n;
    set => n = value;
  }

  /// <summary>Absolute index of refraction; also updates <see cref="cosTotal"/>.</summary>
  public double n
  {
    get => refraction;
    set
    {
      refraction = value;
      cosTotal = value > 1.0 ? Math.Sqrt(value * value - 1.0) / value : 0.0;
    }
  }

  /// <summary>
  /// A Phong material, e.g. <c>new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.8, 0.2, 16)</c>; opaque
  /// (<see cref="Kt"/> 0) with index of refraction <see cref="n"/> 1.5 until set.
  /// </summary>
  /// <param name="color">Surface colour per band (<see cref="Color"/>); the array is kept, not copied.</param>
  /// <param name="ka">Ambient coefficient (<see cref="Ka"/>).</param>
  /// <param name="kd">Diffuse coefficient (<see cref="Kd"/>).</param>
  /// <param name="ks">Specular coefficient (<see cref="Ks"/>).</param>
  /// <param name="h">Specular exponent (<see cref="H"/>): the higher, the smaller and sharper the highlight.</param>
  /// <param name="schlick">Weight of Schlick's Fresnel term (<see cref="Sch"/>), 0 to 1; default 1.</param>
  /// <exception cref="ArgumentNullException"><paramref name="color"/> is null.</exception>
  public PhongMaterial(double[] color, double ka, double kd, double ks, int h, double schlick = 1.0)
  {
    ArgumentNullException.ThrowIfNull(color);
    Color = color;
    Ka = ka;
    Kd = kd;
    Ks = ks;
    H = h;
    Kt = 0.0;
    Sch = schlick;
    n = 1.5;
  }

  /// <summary>The default material: warm yellow, ka 0.2, kd 0.7, ks 0.2, h 16.</summary>
  public PhongMaterial() : this(new[] { 1.0, 0.9, 0.4 }, 0.2, 0.7, 0.2, 16) { }

  /// <summary>A copy of <paramref name="m"/>: every coefficient, and copies of its colour and emission arrays.</summary>
  /// <param name="m">The material to copy.</param>
  /// <exception cref="ArgumentNullException"><paramref name="m"/> is null.</exception>
  public PhongMaterial(PhongMaterial m)
  {
    ArgumentNullException.ThrowIfNull(m);
    Color = (double[])m.Color.Clone();
    Ka = m.Ka;
    Kd = m.Kd;
    Ks = m.Ks;
    H = m.H;
    Kt = m.Kt;
    Sch = m.Sch;
    n = m.n;
    Emission = (double[]?)m.Emission?.Clone();
  }

  /// <summary>A deep copy (see <see cref="PhongMaterial(PhongMaterial)"/>).</summary>
  public virtual object Clone() => new PhongMaterial(this);

  /// <summary>Copies every coefficient of <paramref name="m"/> and shares <paramref name="color"/> (shading scratch copies).</summary>
  internal void CopyFrom(PhongMaterial m, double[] color)
  {
    Color = color;
    Ka = m.Ka;
    Kd = m.Kd;
    Ks = m.Ks;
    H = m.H;
    Kt = m.Kt;
    Sch = m.Sch;
    // cosTotal is a function of the index: remembered for the last index computed, so a copy per hit
    // takes no square root.
    if (m.refraction == memoIndex)
    {
      refraction = m.refraction;
      cosTotal = memoCosTotal;
    }
    else
    {
      n = m.n;
      memoIndex = refraction;
      memoCosTotal = cosTotal;
    }
    Emission = m.Emission;
  }

  // CopyFrom's memo: an index and the cosTotal its setter computed (NaN never matches, so the first copy computes).
  [NonSerialized] double memoIndex = double.NaN, memoCosTotal;
}
