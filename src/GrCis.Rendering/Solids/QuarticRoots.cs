using System;

namespace Rendering;

/// <summary>
/// Real roots of a monic quartic <c>u⁴ + c3 u³ + c2 u² + c1 u + c0</c> on a bounded interval
/// by isolation through its derivatives: the roots of f'' (a quadratic) split the interval
/// into pieces where f' is monotone; the roots of f' found there split it into pieces where
/// f is monotone, and each sign change of f is then refined by safeguarded Newton iteration
/// (bisection whenever Newton leaves the bracket). Nothing relies on closed-form cancellation,
/// so the roots are accurate to a few ulps of the interval whenever they are well conditioned;
/// a double root (tangency) without a sign change is reported as no root.
/// </summary>
internal static class QuarticRoots
{
  /// <summary>Spacing of doubles at 1 (2⁻⁵²); <c>double.Epsilon</c> is the smallest subnormal instead.</summary>
  const double MachineEpsilon = 2.220446049250313e-16;

  /// <summary>
  /// Writes the sign changes of f on [lo, hi] to <paramref name="roots"/> (ascending) and for each
  /// whether f goes from positive to non-positive there (<paramref name="falling"/>). Returns the count (≤ 4).
  /// </summary>
  public static int Solve(double c3, double c2, double c1, double c0, double lo, double hi, Span<double> roots, Span<bool> falling)
  {
    double absTol = (hi - lo) * 1.0e-17;

    // Breakpoints where f' may change monotonicity: roots of f''/2 = 6u² + 3c3 u + c2.
    Span<double> b2 = stackalloc double[4];
    int n2 = 0;
    b2[n2++] = lo;
    double disc = 2.25 * c3 * c3 - 6.0 * c2;
    if (SolidSupport.SolveQuadratic(6.0, 1.5 * c3, c2, disc, out double r0, out double r1))
    {
      if (r0 > lo && r0 < hi)
        b2[n2++] = r0;
      if (r1 > lo && r1 < hi)
        b2[n2++] = r1;
    }
    b2[n2++] = hi;

    // Critical points of f: roots of f' on each monotone piece of f'.
    Span<double> b1 = stackalloc double[5];
    int n1 = 0;
    b1[n1++] = lo;
    for (int i = 0; i + 1 < n2; i++)
    {
      double a = b2[i], b = b2[i + 1];
      double fa = D1(c3, c2, c1, a), fb = D1(c3, c2, c1, b);
      if ((fa > 0.0) != (fb > 0.0))
      {
        double r = Refine(c3, c2, c1, c0, a, b, fa > 0.0, derivative: true, absTol);
        if (r > b1[n1 - 1] && r < hi)
          b1[n1++] = r;
      }
    }
    b1[n1++] = hi;

    // Sign changes of f on each monotone piece.
    int count = 0;
    double fPrev = F(c3, c2, c1, c0, b1[0]);
    for (int i = 0; i + 1 < n1; i++)
    {
      double fNext = F(c3, c2, c1, c0, b1[i + 1]);
      bool pa = fPrev > 0.0, pb = fNext > 0.0;
      if (pa != pb)
      {
        roots[count] = Refine(c3, c2, c1, c0, b1[i], b1[i + 1], pa, derivative: false, absTol);
        falling[count] = pa;
        count++;
      }
      fPrev = fNext;
    }
    return count;
  }

  /// <summary>f(u) by Horner.</summary>
  public static double F(double c3, double c2, double c1, double c0, double u) => (((u + c3) * u + c2) * u + c1) * u + c0;

  /// <summary>f'(u).</summary>
  static double D1(double c3, double c2, double c1, double u) => ((4.0 * u + 3.0 * c3) * u + 2.0 * c2) * u + c1;

  /// <summary>f''(u).</summary>
  static double D2(double c3, double c2, double u) => (12.0 * u + 6.0 * c3) * u + 2.0 * c2;

  /// <summary>
  /// The sign change of g (g = f, or g = f' when <paramref name="derivative"/>) inside [a, b],
  /// where g(a) &gt; 0 exactly when <paramref name="positiveAtA"/>.
  /// </summary>
  static double Refine(double c3, double c2, double c1, double c0, double a, double b, bool positiveAtA, bool derivative, double absTol)
  {
    double x = 0.5 * (a + b);
    for (int iter = 0; iter < 200; iter++)
    {
      double g, dg;
      if (derivative)
      {
        g = D1(c3, c2, c1, x);
        dg = D2(c3, c2, x);
      }
      else
      {
        g = F(c3, c2, c1, c0, x);
        dg = D1(c3, c2, c1, x);
      }
      if (g == 0.0)
        return x;

      // Shrink the bracket on the side with the same sign.
      if ((g > 0.0) == positiveAtA)
        a = x;
      else
        b = x;

      double next = dg != 0.0 ? x - g / dg : double.NaN;
      if (!(next > a && next < b))
        next = 0.5 * (a + b);   // Newton left the bracket: bisect
      if (next == x || b - a <= Math.Max(8.0 * MachineEpsilon * Math.Max(Math.Abs(a), Math.Abs(b)), absTol))
        return next;
      x = next;
    }
    return x;
  }
}
