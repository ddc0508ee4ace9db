using System;
using System.Runtime.CompilerServices;

namespace GrCis.Bench;

/// <summary>
/// The built-in "Two spheres" scene's Whitted ray tree written lean, as a measuring stick for the library's kernel: the
/// same camera, solids, materials, lights, recursion limits (depth 12, importance 0.05) and Phong arithmetic, each
/// solid tested in its local frame through affine matrices and each hit completed through them (as the kernel must, to
/// keep GrCis's bits), but no scene graph, no hit objects, no material copies, no hashes, no observers, and a plain
/// xorshift for the jitter. It traces the kernel's ray tree (<c>LeanWhittedProbeTests</c> compares the counts); its
/// image differs in the bits. What the kernel takes beyond it is the cost of its generality
/// (<see cref="LeanWhittedBenchmarks"/>). Not a renderer: one scene, one thread, nothing reusable.
/// </summary>
public sealed class LeanWhittedProbe
{
  readonly struct V(double x, double y, double z)
  {
    public readonly double X = x, Y = y, Z = z;
    public static V operator +(V a, V b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
    public static V operator -(V a, V b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
    public static V operator -(V a) => new(-a.X, -a.Y, -a.Z);
    public static V operator *(V a, double s) => new(a.X * s, a.Y * s, a.Z * s);
    public static double Dot(V a, V b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
    public V Unit() => this * (1.0 / Math.Sqrt(Dot(this, this)));
    public bool IsZero => X == 0.0 && Y == 0.0 && Z == 0.0;
  }

  sealed record Material(double R, double G, double B, double Ka, double Kd, double Ks, double Kt, double N)
  {
    /// <summary>Cosine of the critical angle inside the material (total internal reflection beyond it).</summary>
    public double CosTotal { get; } = N > 1.0 ? Math.Sqrt(N * N - 1.0) / N : 0.0;
  }

  const int Shininess = 128, MaxLevel = 12;
  const double MinImportance = 0.05, Epsilon2 = 1e-8, CheckerFrequency = 0.6;
  static readonly Material Yellow = new(1.0, 0.8, 0.1, 0.1, 0.6, 0.4, 0.0, 1.0);
  static readonly Material Glass = new(0.0, 0.2, 0.1, 0.05, 0.05, 0.1, 0.9, 1.6);
  static readonly V LightPosition = new(-5.0, 4.0, -3.0);
  const double Ambient = 0.8, LightIntensity = 1.2;

  // Affine 3×4 matrices by rows (x, y, z; the fourth column the translation): the glass ball, the yellow ball (scale
  // 1.2, then moved to (1.5, 0.2, 2.4)) and the floor (the local z = 0 plane turned to face +y, moved to y = -1).
  static readonly double[][] WorldToLocal =
  [
    [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0],
    [1 / 1.2, 0, 0, -1.5 / 1.2, 0, 1 / 1.2, 0, -0.2 / 1.2, 0, 0, 1 / 1.2, -2.4 / 1.2],
    [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 1],
  ];
  static readonly double[][] LocalToWorld =
  [
    [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0],
    [1.2, 0, 0, 1.5, 0, 1.2, 0, 0.2, 0, 0, 1.2, 2.4],
    [1, 0, 0, 0, 0, 0, 1, -1, 0, -1, 0, 0],
  ];

  /// <summary>Closest-hit queries (camera, reflected and refracted rays) of the last render.</summary>
  public long Queries { get; private set; }
  /// <summary>Shadow queries of the last render.</summary>
  public long ShadowQueries { get; private set; }
  /// <summary>Closest-hit queries that hit a solid.</summary>
  public long Hits { get; private set; }

  /// <summary>Renders <paramref name="width"/>×<paramref name="height"/> pixels of n×n jittered samples; linear RGB.</summary>
  public double[] Render(int width, int height, int n)
  {
    Queries = ShadowQueries = Hits = 0;
    V center = new(0.7, 0.5, -5.0), dir = new V(0.0, -0.18, 1.0).Unit(), up = new(0.0, 1.0, 0.0);
    V left = Cross(dir, up).Unit(), top = Cross(left, dir).Unit();
    double halfWidth = Math.Tan(0.5 * (double)(float)(50.0 * Math.PI / 180.0)), halfHeight = halfWidth * height / width;
    V origin = center + dir + top * halfHeight + left * halfWidth;
    V dx = left * (-2.0 * halfWidth / width), dy = top * (-2.0 * halfHeight / height);
    var image = new double[width * height * 3];
    ulong state = 0x9E3779B97F4A7C15UL;
    for (int y = 0; y < height; y++)
      for (int x = 0; x < width; x++)
      {
        double r = 0.0, g = 0.0, b = 0.0;
        for (int s = 0; s < n * n; s++)
        {
          double sx = x + (s % n + Uniform(ref state)) / n, sy = y + (s / n + Uniform(ref state)) / n;
          V d = (origin + dx * sx + dy * sy - center).Unit();
          Shade(center, d, 0, 1.0, out double cr, out double cg, out double cb);
          r += cr;
          g += cg;
          b += cb;
        }
        int i = 3 * (y * width + x);
        image[i] = r / (n * n);
        image[i + 1] = g / (n * n);
        image[i + 2] = b / (n * n);
      }
    return image;
  }

  static double Uniform(ref ulong state)
  {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (state >> 11) * (1.0 / 9007199254740992.0);
  }

  static V Cross(V a, V b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static V Point(double[] m, V p) =>
    new(m[0] * p.X + m[1] * p.Y + m[2] * p.Z + m[3], m[4] * p.X + m[5] * p.Y + m[6] * p.Z + m[7], m[8] * p.X + m[9] * p.Y + m[10] * p.Z + m[11]);
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static V Vector(double[] m, V p) =>
    new(m[0] * p.X + m[1] * p.Y + m[2] * p.Z, m[4] * p.X + m[5] * p.Y + m[6] * p.Z, m[8] * p.X + m[9] * p.Y + m[10] * p.Z);
  // A normal goes through the transpose of world-to-local.
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static V Normal(double[] m, V p) =>
    new(m[0] * p.X + m[4] * p.Y + m[8] * p.Z, m[1] * p.X + m[5] * p.Y + m[9] * p.Z, m[2] * p.X + m[6] * p.Y + m[10] * p.Z);

  /// <summary>The closest solid (0, 1: the balls, 2: the floor; -1: none) hit beyond the epsilon, and its t.</summary>
  int First(V o, V d, out double tBest)
  {
    Queries++;
    double len2 = V.Dot(d, d);
    int best = -1;
    tBest = double.PositiveInfinity;
    for (int k = 0; k < 2; k++)
      if (Ball(k, o, d, len2, out double t1, out double t2))
      {
        if (Beyond(t1, len2))
        {
          if (t1 < tBest)
            (tBest, best) = (t1, k);
        }
        else if (Beyond(t2, len2) && t2 < tBest)
          (tBest, best) = (t2, k);
      }
    if (Floor(o, d, out double t) && Beyond(t, len2) && t < tBest)
      (tBest, best) = (t, 2);
    return best;
  }

  /// <summary>A solid between the point and the light (t in (0, 1) of <paramref name="d"/>).</summary>
  bool Occluded(V o, V d)
  {
    ShadowQueries++;
    double len2 = V.Dot(d, d);
    for (int k = 0; k < 2; k++)
      if (Ball(k, o, d, len2, out double t1, out double t2) &&
          (Beyond(t1, len2) && t1 < 1.0 || Beyond(t2, len2) && t2 < 1.0))
        return true;
    return Floor(o, d, out double t) && Beyond(t, len2) && t < 1.0;
  }

  /// <summary>A root in front of the origin and farther than the epsilon (GrCis's rule for a ray's first record).</summary>
  static bool Beyond(double t, double len2) => t > 0.0 && t * t * len2 > Epsilon2;

  /// <summary>The unit ball of solid <paramref name="k"/>'s frame: both roots of the ray's quadratic.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static bool Ball(int k, V o, V d, double len2, out double t1, out double t2)
  {
    V lo = Point(WorldToLocal[k], o), ld = Vector(WorldToLocal[k], d);
    double a = V.Dot(ld, ld), b = V.Dot(lo, ld), c = V.Dot(lo, lo) - 1.0, disc = b * b - a * c;
    if (disc < 0.0)
    {
      t1 = t2 = 0.0;
      return false;
    }
    double root = Math.Sqrt(disc);
    t1 = (-b - root) / a;
    t2 = (-b + root) / a;
    return true;
  }

  /// <summary>The floor's local z = 0 plane: the ray's t there.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static bool Floor(V o, V d, out double t)
  {
    V lo = Point(WorldToLocal[2], o), ld = Vector(WorldToLocal[2], d);
    t = -lo.Z / ld.Z;
    return t > 0.0;
  }

  static double Power(double x, int e)
  {
    double r = 1.0;
    for (; e > 0; e >>= 1, x *= x)
      if ((e & 1) != 0)
        r *= x;
    return r;
  }

  static V Refract(V normal, double n, V input)
  {
    normal = normal.Unit();
    double d = V.Dot(normal, input);
    if (d < 0.0)
      (d, normal) = (-d, -normal);
    else
      n = 1.0 / n;
    double cos2 = 1.0 - n * n * (1.0 - d * d);
    if (cos2 <= 0.0)
      return default;
    return normal * (n * d - Math.Sqrt(cos2)) - input * n;
  }

  /// <summary>The Phong model for a unit input direction: the diffuse coefficient (when asked) and the specular term.</summary>
  static void Phong(Material m, V normal, V input, V output, bool withDiffuse, out double diffuse, out double specular)
  {
    bool viewOut = V.Dot(output, normal) > 0.0;
    double cosAlpha = V.Dot(input, normal), coefficient = 1.0, ks = m.Ks;
    V r = default;
    if (viewOut == cosAlpha > 0.0)
    {
      r = normal * (2.0 * cosAlpha) - input;
      // Total internal reflection takes the transmitted energy.
      if (cosAlpha <= 0.0 && -cosAlpha <= m.CosTotal)
        ks = Math.Min(ks + m.Kt, 1.0 - m.Kd);
    }
    else if (withDiffuse)
    {
      r = Refract(normal, m.N, input);
      coefficient = m.Kt;
    }
    diffuse = withDiffuse ? coefficient * m.Kd * Math.Abs(cosAlpha) : 0.0;
    specular = 0.0;
    double cosBeta = r.IsZero ? 0.0 : V.Dot(r, output);
    if (cosBeta > 0.0)
      specular = coefficient * ks * Power(cosBeta, Shininess);
  }

  void Shade(V o, V d, int depth, double importance, out double r, out double g, out double b)
  {
    int k = First(o, d, out double t);
    if (k < 0)
    {
      (r, g, b) = (0.0, 0.05, 0.07);
      return;
    }
    Hits++;
    V local = Point(WorldToLocal[k], o) + Vector(WorldToLocal[k], d) * t;
    V p = Point(LocalToWorld[k], local);
    V normal = Normal(WorldToLocal[k], k < 2 ? local : new V(0.0, 0.0, 1.0)).Unit();
    Material m = k == 0 ? Glass : Yellow;
    double sr = m.R, sg = m.G, sb = m.B;
    if (k == 2)
      (sr, sg, sb) = ((long)Math.Floor(local.X * CheckerFrequency) + (long)Math.Floor(local.Y * CheckerFrequency) & 1) != 0
        ? (1.0, 1.0, 1.0)
        : (0.3, 0.0, 0.0);

    V viewer = -d.Unit();
    double ambient = Ambient * (V.Dot(viewer, normal) > 0.0 ? m.Ka : m.Ka * m.Kt);
    (r, g, b) = (ambient * sr, ambient * sg, ambient * sb);
    V toLight = LightPosition - p;
    if (V.Dot(toLight, normal) > 0.0 && !Occluded(p, toLight))
    {
      Phong(m, normal, toLight.Unit(), viewer, true, out double diffuse, out double specular);
      r += LightIntensity * (diffuse * sr + specular);
      g += LightIntensity * (diffuse * sg + specular);
      b += LightIntensity * (diffuse * sb + specular);
    }
    if (depth++ >= MaxLevel)
      return;

    V viewerUnit = viewer.Unit();
    V reflected = normal * (2.0 * V.Dot(normal, viewer)) - viewer;
    Phong(m, normal, viewerUnit, reflected, false, out _, out double ks);
    if (importance * ks >= MinImportance)
    {
      Shade(p, reflected, depth, importance * ks, out double rr, out double rg, out double rb);
      r += ks * rr;
      g += ks * rg;
      b += ks * rb;
    }
    if (m.Kt <= 0.0 || importance * m.Kt < MinImportance)
      return;
    V refracted = Refract(normal, m.N, viewerUnit);
    if (refracted.IsZero)
      return;
    Shade(p, refracted, depth, importance * m.Kt, out double tr, out double tg, out double tb);
    r += m.Kt * tr;
    g += m.Kt * tg;
    b += m.Kt * tb;
  }
}
