using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The scattering a <see cref="PathTracing"/> vertex uses, read from GrCis's Phong parameters: a Lambertian
/// lobe of albedo Kd·colour, an energy-conserving (normalised) Phong lobe of weight Ks and exponent H around
/// the mirror direction (an ideal mirror from <see cref="PathTracing.MirrorExponent"/> on), and for Kt &gt; 0 a
/// smooth dielectric of index n (exact Fresnel, total internal reflection) of weight Kt. When Kd·max(colour) +
/// Ks + Kt exceeds 1 the three are scaled down to sum to 1, so no surface reflects more light than it receives.
/// </summary>
internal struct PathBsdf
{
  Vector3d nf;        // normal on the side the light leaves towards (wo's side)
  Vector3d wo;        // towards the previous vertex
  Vector3d mirror;    // wo mirrored about nf
  Rgb diffuse;        // albedo of the Lambertian lobe
  double ks, kt, eta; // weights and the relative index (inside over outside)
  double exponent;
  bool glossyIsMirror, entering;
  double pD, pS, pT;  // lobe selection probabilities (sum 1)
  IScatteringMaterial? own;   // a material's own scattering, when it supplies one
  Intersection? hit;
  double[]? buffer;

  /// <summary>False when the surface scatters nothing (black): the path ends.</summary>
  public bool Scatters { get; private set; }

  /// <summary>True when some lobe is not a delta (so light sampling can reach it).</summary>
  public readonly bool HasSmooth => own != null || pD > 0.0 || (pS > 0.0 && !glossyIsMirror);

  /// <summary>True when one Phong lobe carries all the scattering: <see cref="Sample"/> takes it whatever its choice value.</summary>
  public readonly bool SingleLobe => own == null && (pD == 1.0 || pS == 1.0 || pT == 1.0);

  /// <summary>False for an ideal mirror alone: its one direction needs no (u, v).</summary>
  public readonly bool SamplesDirection => !(own == null && pS == 1.0 && glossyIsMirror);

  /// <summary>The facing normal (on the side of the outgoing direction).</summary>
  public readonly Vector3d FacingNormal => nf;

  /// <summary>Scattering at a point of outward normal <paramref name="normal"/> hit by a ray of unit direction <paramref name="direction"/>.</summary>
  public static PathBsdf For(IMaterial? material, ReadOnlySpan<double> surface, Vector3d normal, Vector3d direction, int mirrorExponent) =>
    For(material, null, null, surface, normal, direction, mirrorExponent);

  /// <summary>
  /// Scattering at <paramref name="hit"/>: the material's own (<see cref="IScatteringMaterial"/>, given <paramref name="hit"/>
  /// and a per-worker <paramref name="buffer"/> of the bands) when it supplies one, else read from its Phong parameters.
  /// </summary>
  public static PathBsdf For(IMaterial? material, Intersection? hit, double[]? buffer, ReadOnlySpan<double> surface, Vector3d normal, Vector3d direction, int mirrorExponent)
  {
    var s = new PathBsdf { wo = -direction };
    double cosO = Vector3d.Dot(normal, s.wo);
    s.entering = cosO > 0.0;
    s.nf = s.entering ? normal : -normal;
    s.mirror = 2.0 * Math.Abs(cosO) * s.nf - s.wo;
    if (HasOwnScattering(material) && hit != null && buffer != null)
    {
      s.own = (IScatteringMaterial)material!;
      s.hit = hit;
      s.buffer = buffer;
      s.Scatters = true;
      return s;
    }

    Rgb colour = Rgb.From(surface);
    double kd, ks, kt;
    int h;
    if (material is PhongMaterial pm)
    {
      kd = pm.Kd;
      ks = pm.Ks;
      kt = pm.Kt;
      h = pm.H;
    }
    else
    {
      // A material without Phong coefficients: Lambertian in its colour, transparent by its Kt.
      kt = material?.Kt ?? 0.0;
      kd = 1.0 - kt;
      ks = 0.0;
      h = 0;
    }
    kd = Math.Max(kd, 0.0);
    ks = Math.Max(ks, 0.0);
    kt = Math.Max(kt, 0.0);
    double sum = kd * Math.Max(colour.Max, 0.0) + ks + kt;
    if (sum > 1.0)
    {
      kd /= sum;
      ks /= sum;
      kt /= sum;
    }
    s.diffuse = new Rgb(Math.Max(colour.R, 0.0), Math.Max(colour.G, 0.0), Math.Max(colour.B, 0.0)) * kd;
    s.ks = ks;
    s.kt = kt;
    s.exponent = Math.Max(h, 0);
    s.glossyIsMirror = h >= mirrorExponent;
    double n = material?.n ?? 1.0;
    s.eta = n > 0.0 ? n : 1.0;

    s.Scatters = LobeProbabilities(s.diffuse.Average, ks, kt, out s.pD, out s.pS, out s.pT);
    return s;
  }

  /// <summary>
  /// The lobe selection probabilities: each weight over their sum (all 0 and false when the sum is not positive). A
  /// lone finite lobe, the usual case, needs no division: x/x is exactly 1 and 0/x exactly 0.
  /// </summary>
  internal static bool LobeProbabilities(double wD, double wS, double wT, out double pD, out double pS, out double pT)
  {
    pD = pS = pT = 0.0;
    double total = wD + wS + wT;
    if (!(total > 0.0))
      return false;
    if (wS == 0.0 && wT == 0.0 && double.IsFinite(wD))
      pD = 1.0;
    else if (wD == 0.0 && wT == 0.0 && double.IsFinite(wS))
      pS = 1.0;
    else if (wD == 0.0 && wS == 0.0 && double.IsFinite(wT))
      pT = 1.0;
    else
    {
      pD = wD / total;
      pS = wS / total;
      pT = wT / total;
    }
    return true;
  }

  /// <summary>
  /// True when <paramref name="material"/> supplies its own scattering (<see cref="IScatteringMaterial"/>); the
  /// library's <see cref="PhongMaterial"/> does not.
  /// </summary>
  public static bool HasOwnScattering(IMaterial? material) => material is IScatteringMaterial;

  /// <summary>The smooth (non-delta) part of the BSDF for light arriving from <paramref name="wi"/>, without the cosine.</summary>
  public readonly Rgb Eval(Vector3d wi)
  {
    if (own == null && Vector3d.Dot(wi, nf) <= 0.0)
      return Rgb.Zero;
    return EvalAbove(wi);
  }

  /// <summary>
  /// <see cref="Eval"/> for a <paramref name="wi"/> the caller has already found above the surface (cos θ = wi·nf &gt; 0):
  /// the same values without testing the side again.
  /// </summary>
  public readonly Rgb EvalAbove(in Vector3d wi)
  {
    if (own != null)
    {
      own.Eval(hit!, wo, wi, buffer!);
      return Rgb.From(buffer);
    }
    Rgb f = diffuse * (1.0 / Math.PI);
    if (ks > 0.0 && !glossyIsMirror)
    {
      double c = Vector3d.Dot(wi, mirror);
      if (c > 0.0)
        f += new Rgb(ks * (exponent + 2.0) / (2.0 * Math.PI) * Math.Pow(c, exponent));
    }
    return f;
  }

  /// <summary>Density (per steradian) with which <see cref="Sample"/> picks <paramref name="wi"/> through a smooth lobe.</summary>
  public readonly double Pdf(Vector3d wi)
  {
    if (own != null)
      return own.Pdf(hit!, wo, wi);
    double cos = Vector3d.Dot(wi, nf);
    return cos <= 0.0 ? 0.0 : PdfAbove(wi, cos);
  }

  /// <summary><see cref="Pdf"/> for a <paramref name="wi"/> above the surface whose cosine wi·nf (&gt; 0) the caller has at hand.</summary>
  public readonly double PdfAbove(in Vector3d wi, double cos)
  {
    if (own != null)
      return own.Pdf(hit!, wo, wi);
    double p = pD * cos / Math.PI;
    if (pS > 0.0 && !glossyIsMirror)
      p += pS * SampleWarp.PowerCosinePdf(Vector3d.Dot(wi, mirror), exponent);
    return p;
  }

  /// <summary>
  /// Samples an incoming direction: <paramref name="choice"/> picks the lobe, (u, v) the direction in it.
  /// <paramref name="weight"/> is f·cos/pdf; <paramref name="delta"/> says a mirror or dielectric chose it (then
  /// <paramref name="pdf"/> is 0). False when the sample carries nothing (it fell below the surface).
  /// </summary>
  public readonly bool Sample(double choice, double u, double v, out Vector3d wi, out Rgb weight, out double pdf, out bool delta)
  {
    weight = Rgb.Zero;
    pdf = 0.0;
    delta = false;
    wi = mirror;
    if (own != null)
    {
      if (!own.Sample(hit!, wo, choice, u, v, out wi, buffer!, out pdf, out delta))
        return false;
      weight = Rgb.From(buffer);
      return true;
    }
    if (choice < pD || (choice < pD + pS && !glossyIsMirror))
    {
      wi = choice < pD ? SampleWarp.CosineHemisphere(u, v, nf) : SampleWarp.PowerCosine(u, v, mirror, exponent);
      double cos = Vector3d.Dot(wi, nf);
      if (cos <= 0.0)
        return false;
      pdf = PdfAbove(wi, cos);
      if (pdf <= 0.0)
        return false;
      weight = EvalAbove(wi) * (cos / pdf);
      return true;
    }
    delta = true;
    if (choice < pD + pS)
    {
      weight = new Rgb(ks / pS);
      return true;
    }
    // Smooth dielectric: reflect with the Fresnel probability, else refract; the weights cancel to kt / pT.
    double cosI = Vector3d.Dot(wo, nf);
    double ratio = entering ? 1.0 / eta : eta;   // outside over inside index when entering
    double sin2T = ratio * ratio * Math.Max(0.0, 1.0 - cosI * cosI);
    double fresnel = sin2T >= 1.0 ? 1.0 : Fresnel(cosI, Math.Sqrt(1.0 - sin2T), ratio);
    weight = new Rgb(kt / pT);
    if (u < fresnel)
      return true;
    double cosT = Math.Sqrt(1.0 - sin2T);
    wi = -ratio * wo + (ratio * cosI - cosT) * nf;
    return true;
  }

  /// <summary>Unpolarised Fresnel reflectance; <paramref name="ratio"/> = incident over transmitted index.</summary>
  internal static double Fresnel(double cosI, double cosT, double ratio)
  {
    double rs = (ratio * cosI - cosT) / (ratio * cosI + cosT);
    double rp = (ratio * cosT - cosI) / (ratio * cosT + cosI);
    return 0.5 * (rs * rs + rp * rp);
  }
}
