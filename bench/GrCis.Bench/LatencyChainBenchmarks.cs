using System.Runtime.Intrinsics;
using BenchmarkDotNet.Attributes;

namespace GrCis.Bench;

/// <summary>
/// How much a two-lane kernel could gain at most on this processor: the arithmetic of a ray's path (normalize, the
/// ball's roots, the hit's normal, a Phong power, the mirrored direction; each step waiting on the last one's square
/// roots and divisions, with a data-dependent branch) for many independent rays, one ray after another against two
/// rays interleaved in one instruction stream and against four rays in the lanes of 256-bit vectors (both sides of the
/// branch computed, each lane taking its own). Same numbers every way (the sums are compared). The scalar kernel is
/// the baseline; a ratio well below 1 says the processor idles on the chain's latencies, which running two samples'
/// rays side by side would fill; the lanes' ratio bounds what a kernel running several rays per stage could gain on
/// the arithmetic (docs/performance.md, "What is left").
/// <c>dotnet run -c Release --project bench/GrCis.Bench -- --filter *LatencyChain* --job short</c>
/// </summary>
public class LatencyChainBenchmarks
{
  const int Rays = 200_000, Depth = 5;   // Rays: a multiple of 4 (pairs and lanes take whole groups)
  double[] starts = [];

  [GlobalSetup]
  public void Setup()
  {
    var random = new System.Random(1);
    starts = new double[Rays * 3];
    for (int i = 0; i < starts.Length; i++)
      starts[i] = random.NextDouble() - 0.3;
    if (OneByOne() != Pairs() || OneByOne() != Lanes())
      throw new System.InvalidOperationException("the interleaved chains compute different numbers");
  }

  [Benchmark(Baseline = true)]
  public double OneByOne()
  {
    double sum = 0.0;
    for (int i = 0; i < Rays; i++)
    {
      double x = starts[3 * i], y = starts[3 * i + 1], z = starts[3 * i + 2];
      sum += Path(ref x, ref y, ref z);
    }
    return sum;
  }

  [Benchmark]
  public double Pairs()
  {
    double sum = 0.0;
    for (int i = 0; i < Rays; i += 2)
    {
      double x = starts[3 * i], y = starts[3 * i + 1], z = starts[3 * i + 2];
      double x2 = starts[3 * i + 3], y2 = starts[3 * i + 4], z2 = starts[3 * i + 5];
      double a = 0.0, b = 0.0;
      for (int d = 0; d < Depth; d++)
      {
        // The two rays' steps written side by side (inlined), so their latencies overlap.
        a += Step(ref x, ref y, ref z);
        b += Step(ref x2, ref y2, ref z2);
      }
      sum += a;
      sum += b;
    }
    return sum;
  }

  /// <summary>Four rays at a time, one per lane of a 256-bit vector (the scalar steps where vectors are not accelerated).</summary>
  [Benchmark]
  public double Lanes()
  {
    if (!Vector256.IsHardwareAccelerated)
      return OneByOne();
    double sum = 0.0;
    for (int i = 0; i < Rays; i += 4)
    {
      var x = Vector256.Create(starts[3 * i], starts[3 * i + 3], starts[3 * i + 6], starts[3 * i + 9]);
      var y = Vector256.Create(starts[3 * i + 1], starts[3 * i + 4], starts[3 * i + 7], starts[3 * i + 10]);
      var z = Vector256.Create(starts[3 * i + 2], starts[3 * i + 5], starts[3 * i + 8], starts[3 * i + 11]);
      Vector256<double> a = Vector256<double>.Zero;
      for (int d = 0; d < Depth; d++)
        a += Step(ref x, ref y, ref z);
      // The rays' sums in ray order, as one ray after another adds them.
      sum += a.GetElement(0);
      sum += a.GetElement(1);
      sum += a.GetElement(2);
      sum += a.GetElement(3);
    }
    return sum;
  }

  static double Path(ref double x, ref double y, ref double z)
  {
    double a = 0.0;
    for (int d = 0; d < Depth; d++)
      a += Step(ref x, ref y, ref z);
    return a;
  }

  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  static double Step(ref double x, ref double y, ref double z)
  {
    double s = 1.0 / System.Math.Sqrt(x * x + y * y + z * z);
    x *= s; y *= s; z *= s;
    double half = x * 0.3 + y * 0.2 + z * 0.9, disc = half * half - 0.5;
    if (disc > 0.0)
    {
      double t = (half - System.Math.Sqrt(disc)) / 1.0001;
      x = x * t + 0.1; y = y * t - 0.2; z = z * t + 0.05;
    }
    else
    {
      x += 0.3; y -= 0.1;
    }
    double inv = 1.0 / System.Math.Sqrt(x * x + y * y + z * z);
    double nx = x * inv, ny = y * inv, nz = z * inv;
    double c = nx * 0.5 + ny * 0.6 + nz * 0.62, p = c * c;
    p *= p; p *= p; p *= p; p *= p;
    x = nx - c; y = ny - 1.2 * c; z = nz - 1.24 * c + 1e-3;
    return p + c;
  }

  /// <summary><see cref="Step(ref double, ref double, ref double)"/> of four rays, lane by lane the same operations.</summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  static Vector256<double> Step(ref Vector256<double> x, ref Vector256<double> y, ref Vector256<double> z)
  {
    Vector256<double> one = Vector256.Create(1.0);
    Vector256<double> s = one / Vector256.Sqrt(x * x + y * y + z * z);
    x *= s; y *= s; z *= s;
    Vector256<double> half = x * 0.3 + y * 0.2 + z * 0.9, disc = half * half - Vector256.Create(0.5);
    Vector256<double> hits = Vector256.GreaterThan(disc, Vector256<double>.Zero);
    Vector256<double> t = (half - Vector256.Sqrt(disc)) / Vector256.Create(1.0001);
    x = Vector256.ConditionalSelect(hits, x * t + Vector256.Create(0.1), x + Vector256.Create(0.3));
    y = Vector256.ConditionalSelect(hits, y * t - Vector256.Create(0.2), y - Vector256.Create(0.1));
    z = Vector256.ConditionalSelect(hits, z * t + Vector256.Create(0.05), z);
    Vector256<double> inv = one / Vector256.Sqrt(x * x + y * y + z * z);
    Vector256<double> nx = x * inv, ny = y * inv, nz = z * inv;
    Vector256<double> c = nx * 0.5 + ny * 0.6 + nz * 0.62, p = c * c;
    p *= p; p *= p; p *= p; p *= p;
    x = nx - c; y = ny - 1.2 * c; z = nz - 1.24 * c + Vector256.Create(1e-3);
    return p + c;
  }
}
