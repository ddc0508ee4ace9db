using System;
using System.Diagnostics;
using System.Threading;

namespace GrCis.Cli.Bench;

/// <summary>
/// What N threads can gain on this machine at best: the same register-only arithmetic loop run on one
/// thread, then on N threads at once, as throughput N·t₁/t_N. A VM's "cores" may be hyperthread pairs
/// or shared with other guests; a renderer's thread scaling is judged against this ceiling, not against N.
/// </summary>
public static class ParallelCeiling
{
  /// <summary>Best of <paramref name="rounds"/> alternating one-thread / N-thread runs of about <paramref name="seconds"/> each.</summary>
  public static double Measure(int threads, double seconds = 0.3, int rounds = 3)
  {
    if (threads <= 1)
      return 1.0;
    long iterations = Calibrate(seconds);
    double best1 = double.MaxValue, bestN = double.MaxValue;
    for (int r = 0; r < rounds; r++)
    {
      best1 = Math.Min(best1, Time(1, iterations));
      bestN = Math.Min(bestN, Time(threads, iterations));
    }
    return threads * best1 / bestN;
  }

  static long Calibrate(double seconds)
  {
    long n = 1 << 20;
    var clock = Stopwatch.StartNew();
    Sink(Spin(n));
    double t = Math.Max(clock.Elapsed.TotalSeconds, 1e-6);
    return Math.Max(n, (long)(n * seconds / t));
  }

  /// <summary>Wall seconds for <paramref name="threads"/> threads each running the loop once, started together.</summary>
  static double Time(int threads, long iterations)
  {
    using var start = new ManualResetEventSlim(false);
    var workers = new Thread[threads];
    for (int i = 0; i < threads; i++)
    {
      workers[i] = new Thread(() => { start.Wait(); Sink(Spin(iterations)); }) { IsBackground = true };
      workers[i].Start();
    }
    Thread.Sleep(20);   // let every worker reach the gate
    var clock = Stopwatch.StartNew();
    start.Set();
    foreach (Thread w in workers)
      w.Join();
    return clock.Elapsed.TotalSeconds;
  }

  // Twelve independent chains of multiply-then-add: enough to fill a core's FP pipes (a latency-bound loop
  // would leave room for an SMT sibling and hide that two "cores" share one), touching no memory.
  static double Spin(long n)
  {
    double a = 1.0, b = 1.1, c = 1.2, d = 1.3, e = 1.4, f = 1.5;
    double g = 1.6, h = 1.7, i = 1.8, j = 1.9, k = 2.0, l = 2.1;
    for (long it = 0; it < n; it++)
    {
      a = a * 0.999999 + 1e-7; b = b * 0.999998 + 2e-7; c = c * 0.999997 + 3e-7;
      d = d * 0.999996 + 4e-7; e = e * 0.999995 + 5e-7; f = f * 0.999994 + 6e-7;
      g = g * 0.999993 + 7e-7; h = h * 0.999992 + 8e-7; i = i * 0.999991 + 9e-7;
      j = j * 0.999990 + 1e-6; k = k * 0.999989 + 2e-6; l = l * 0.999988 + 3e-6;
    }
    return a + b + c + d + e + f + g + h + i + j + k + l;
  }

  static double sink;
  static void Sink(double v) => Volatile.Write(ref sink, v);
}
