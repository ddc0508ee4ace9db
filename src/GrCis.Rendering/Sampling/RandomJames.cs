using System;

namespace MathSupport;

/// <summary>
/// The Marsaglia–Zaman "universal" generator (RANMAR, period about 2^144) in the form F. James
/// published: a lagged Fibonacci sequence of 97 24-bit fractions combined with an arithmetic one.
/// </summary>
public class RandomJames
{
  const int Lags = 97;
  const double CInit = 362436.0 / 16777216.0;
  const double CD = 7654321.0 / 16777216.0;
  const double CM = 16777213.0 / 16777216.0;

  readonly double[] u = new double[Lags];
  double c;
  int i97, j97;

  // Lazy seeding: Reset stores the seed, the first draw initialises (a pixel that never draws pays nothing).
  bool pending;
  ulong pendingSeed;

  /// <summary>Seeded with Marsaglia's default pair (1802, 9373).</summary>
  public RandomJames() => Reset(1802, 9373);

  /// <summary>A generator seeded from one number (<see cref="Reset(long)"/>): the same seed gives the same sequence.</summary>
  /// <param name="seed">Any number; it is split into Marsaglia's two seeds.</param>
  public RandomJames(long seed) => Reset(seed);

  /// <summary>A generator seeded with Marsaglia's two seeds (<see cref="Reset(int, int)"/>).</summary>
  /// <param name="ij">First seed, clamped to 0 … 31328.</param>
  /// <param name="kl">Second seed, clamped to 0 … 30081.</param>
  public RandomJames(int ij, int kl) => Reset(ij, kl);

  /// <summary>True once the generator has been seeded.</summary>
  public bool Ok { get; private set; }

  /// <summary>Marsaglia's initialisation from two seeds, clamped to 0 ≤ ij ≤ 31328 and 0 ≤ kl ≤ 30081.</summary>
  public void Reset(int ij, int kl)
  {
    ij = Math.Clamp(ij, 0, 31328);
    kl = Math.Clamp(kl, 0, 30081);

    int i = (ij / 177) % 177 + 2, j = ij % 177 + 2;
    int k = (kl / 169) % 178 + 1, l = kl % 169;
    for (int ii = 0; ii < Lags; ii++)
    {
      double s = 0.0, t = 0.5;
      for (int jj = 0; jj < 24; jj++)
      {
        int m = (((i * j) % 179) * k) % 179;
        i = j; j = k; k = m;
        l = (53 * l + 1) % 169;
        if ((l * m) % 64 >= 32)
          s += t;
        t *= 0.5;
      }
      u[ii] = s;
    }
    c = CInit;
    i97 = Lags - 1;
    j97 = 32;
    pending = false;
    fresh = false;
    normalReady = false;
    Ok = true;
  }

  /// <summary>Seeds from one number, split into the two Marsaglia seeds.</summary>
  public void Reset(long ijkl)
  {
    long s = Math.Abs(ijkl % (31329L * 30082L));
    Reset((int)(s / 30082), (int)(s % 30082));
  }

  /// <summary>Seeds from the clock; returns the combined seed so a run can be repeated.</summary>
  public long Randomize()
  {
    long ticks = DateTime.UtcNow.Ticks;
    int s1 = (int)((ticks / TimeSpan.TicksPerSecond) % 31329);
    int s2 = (int)(ticks % 30082);
    Reset(s1, s2);
    return s1 * 30082L + s2;
  }

  /// <summary>Marsaglia's published check: seeds (1802, 9373), 20,000 draws, then six known values.</summary>
  public bool Validate()
  {
    Reset(1802, 9373);
    for (int i = 0; i < 20000; i++)
      UniformNumber();
    ReadOnlySpan<int> expected = [6533892, 14220222, 7275067, 6172232, 8354498, 10633180];
    bool ok = true;
    foreach (int e in expected)
      ok &= (int)(UniformNumber() * 4096.0 * 4096.0 + 0.5) == e;
    return ok;
  }

  /// <summary>
  /// Cheap, lazy reseeding for per-pixel determinism: the lag table is the SplitMix64 stream of
  /// <paramref name="seed"/>, filled as draws need it. Different seeds give independent-looking streams.
  /// </summary>
  public void ResetFast(ulong seed)
  {
    pendingSeed = seed;
    pending = true;
  }

  // The lag table of a ResetFast seed is filled lazily: the first FreshDraws draws read only u[96..64]
  // and u[32..0], each computed on demand (SplitMix64 is random access); the rest is filled when a pixel
  // draws more. A 16-sample pixel (32 draws) computes 64 entries instead of 97. Same numbers either way.
  const int FreshDraws = 33;
  bool fresh;
  int freshCount;

  void InitFromPending()
  {
    c = CInit;
    i97 = Lags - 1;
    j97 = 32;
    pending = false;
    fresh = true;
    freshCount = 0;
    normalReady = false;
    Ok = true;
  }

  /// <summary>Entry <paramref name="k"/> of the table a ResetFast seed fills: the (k+1)-th SplitMix64 output, top 24 bits.</summary>
  double SeedEntry(int k)
  {
    ulong z = pendingSeed + (ulong)(k + 1) * 0x9E3779B97F4A7C15UL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
    return ((z ^ (z >> 31)) >> 40) * (1.0 / 16777216.0);
  }

  double FreshNumber()
  {
    double[] uu = u;
    int n = freshCount;
    if (n < FreshDraws)
    {
      // i97 = 96 − n and j97 = 32 − n still hold seed values; keep the lower one (read again after the wrap).
      freshCount = n + 1;
      double b = uu[j97] = SeedEntry(j97);
      double uni = SeedEntry(i97) - b;
      uni -= Math.Floor(uni);
      uu[i97] = uni;
      i97--;
      j97 = j97 == 0 ? Lags - 1 : j97 - 1;
      return Carry(uni);
    }
    // Entries not read yet: j97 + 1 … i97 (33 … 63).
    for (int k = FreshDraws; k <= i97; k++)
      uu[k] = SeedEntry(k);
    fresh = false;
    return Step();
  }

  /// <summary>Next number in [0, 1), a multiple of 2^-24.</summary>
  public double UniformNumber()
  {
    if (pending | fresh | !Ok)
      return FirstNumbers();
    return Step();
  }

  // The seeding branches live here so the hot step stays small.
  double FirstNumbers()
  {
    if (!Ok && !pending)
      return 0.0;
    if (pending)
      InitFromPending();
    return FreshNumber();
  }

  /// <summary>
  /// One RANMAR step without a sign branch: every value is a multiple of 2^-24 in (−1, 1), so
  /// x − ⌊x⌋ is exactly "x + 1 when negative" and c − ⌊c⌋·CM exactly "c + CM when negative".
  /// </summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  double Step()
  {
    double[] uu = u;
    int i = i97, j = j97;
    double uni = uu[i] - uu[j];
    uni -= Math.Floor(uni);
    uu[i] = uni;
    i97 = i == 0 ? Lags - 1 : i - 1;
    j97 = j == 0 ? Lags - 1 : j - 1;
    return Carry(uni);
  }

  /// <summary>The step's second half: advance the arithmetic sequence c and subtract it (mod 1, branch-free).</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  double Carry(double uni)
  {
    double cc = c - CD;
    cc -= Math.Floor(cc) * CM;
    c = cc;
    uni -= cc;
    return uni - Math.Floor(uni);
  }

  /// <summary>Uniform number in [min, max); min when the range is empty.</summary>
  public double UniformNumber(double min, double max) => RandomDouble(min, max);

  /// <summary>Uniform number in [min, max); min when the range is empty.</summary>
  public double RandomDouble(double min, double max) => min >= max ? min : min + (max - min) * UniformNumber();

  /// <summary>Uniform number in [min, max) in single precision (rounding may give max itself); min when the range is empty.</summary>
  public float RandomFloat(float min, float max) => min >= max ? min : min + (max - min) * (float)UniformNumber();

  /// <summary>Fills the whole of <paramref name="vec"/> with uniform numbers in [0, 1).</summary>
  public void UniformNumbers(double[] vec) => UniformNumbers(vec, 0, vec.Length);

  /// <summary>Fills <paramref name="number"/> elements of <paramref name="vec"/> from index <paramref name="from"/> on (stopping at its end) with uniform numbers in [0, 1).</summary>
  /// <exception cref="ArgumentNullException"><paramref name="vec"/> is null.</exception>
  public void UniformNumbers(double[] vec, int from, int number)
  {
    ArgumentNullException.ThrowIfNull(vec);
    for (int i = from; i < from + number && i < vec.Length; i++)
      vec[i] = UniformNumber();
  }

  /// <summary>Uniform integer in [min, max], both ends included; min when max ≤ min.</summary>
  public int RandomInteger(int min, int max)
  {
    if (min >= max)
      return min;
    long span = (long)max + 1 - min;
    return (int)(min + Math.Min((long)Math.Floor(span * UniformNumber()), span - 1));
  }

  bool normalReady;
  double normalValue;

  /// <summary>Normally distributed number (polar Box–Muller; the second value is kept for the next call).</summary>
  public double Normal(double mu, double sigma)
  {
    if (normalReady)
    {
      normalReady = false;
      return mu + sigma * normalValue;
    }
    double v1, v2, s;
    do
    {
      v1 = RandomDouble(-1.0, 1.0);
      v2 = RandomDouble(-1.0, 1.0);
      s = v1 * v1 + v2 * v2;
    } while (s >= 1.0 || s < 2.0 * double.Epsilon);
    double f = Math.Sqrt(-2.0 * Math.Log(s) / s);
    normalValue = v2 * f;
    normalReady = true;
    return mu + sigma * v1 * f;
  }

  /// <summary>Uniform random point of the triangle (a, b, c).</summary>
  public void RandomPointFromTriangle(OpenTK.Mathematics.Vector3d a, OpenTK.Mathematics.Vector3d b, OpenTK.Mathematics.Vector3d c, out OpenTK.Mathematics.Vector3d result)
  {
    double uu = UniformNumber(), vv = UniformNumber();
    if (uu + vv > 1.0)
    {
      uu = 1.0 - uu;
      vv = 1.0 - vv;
    }
    result = a + uu * (b - a) + vv * (c - a);
  }

  /// <summary>Uniform direction on the sphere between two sines of latitude (z is up).</summary>
  public void UniformDirection(double minLat, double maxLat, out OpenTK.Mathematics.Vector3d result)
  {
    double sinLat = RandomDouble(Math.Max(-1.0, minLat), Math.Min(1.0, maxLat));
    double cosLat = Math.Sqrt(1.0 - sinLat * sinLat);
    double lon = UniformNumber() * 2.0 * Math.PI;
    result = new OpenTK.Mathematics.Vector3d(Math.Cos(lon) * cosLat, Math.Sin(lon) * cosLat, sinLat);
  }

  /// <summary>State of a random permutation drawn element by element (a cyclic list of what is left).</summary>
  public class Permutation
  {
    /// <summary>The cyclic list of the elements left: <c>perm[i]</c> is the element after i.</summary>
    public int[] perm = Array.Empty<int>();
    /// <summary>Where the walk through the cyclic list stands.</summary>
    public int permPtr;
    /// <summary>Number of elements not drawn yet.</summary>
    public int permSize;
  }

  /// <summary>Starts a random permutation of 0..size-1 and returns its first element (-1 for size &lt; 1).</summary>
  public int PermutationFirst(int size, ref Permutation? perm)
  {
    if (size < 1)
      return -1;
    perm ??= new Permutation();
    perm.permSize = size;
    if (perm.perm.Length < size)
      perm.perm = new int[size];
    for (int i = 0; i < size - 1; i++)
      perm.perm[i] = i + 1;
    perm.perm[size - 1] = 0;
    perm.permPtr = 0;
    return PermutationNext(ref perm);
  }

  /// <summary>Next element of the permutation, or -1 when it is exhausted.</summary>
  public int PermutationNext(ref Permutation? perm)
  {
    if (perm == null || perm.permSize <= 0)
      return -1;
    int steps = (int)(UniformNumber() * perm.permSize);
    int[] p = perm.perm;
    while (steps-- > 0)
      perm.permPtr = p[perm.permPtr];
    int result = p[perm.permPtr];
    p[perm.permPtr] = p[result];
    perm.permSize--;
    return result;
  }
}
