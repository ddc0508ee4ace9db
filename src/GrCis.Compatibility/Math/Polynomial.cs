using System;

namespace MathSupport;

/// <summary>
/// GrCis's polynomial of degree at most 4, <c>A + B x + C x² + D x³ + E x⁴</c> (A is the constant term),
/// with closed-form real roots. Roots are written to the array in ascending order; the methods return
/// how many there are (a double root counts once). Unlike GrCis's <c>SolveQuadratic</c>, which returned
/// the reciprocals of the roots whenever A ≠ C, these are the roots; each is polished by Newton steps.
/// </summary>
public class Polynomial
{
  protected static double EPSILON = 1.0e-10;
  protected static double COEFF_LIMIT = 1.0e-16;
  protected static double PI_2_3 = 2.0 * Math.PI / 3.0;
  protected static double PI_4_3 = 4.0 * Math.PI / 3.0;

  /// <summary>Degree as set (2, 3 or 4; 0 for the null polynomial).</summary>
  protected int n;

  protected double A, B, C, D, E;

  public Polynomial()
  {
  }

  public Polynomial(Polynomial p)
  {
    ArgumentNullException.ThrowIfNull(p);
    (n, A, B, C, D, E) = (p.n, p.A, p.B, p.C, p.D, p.E);
  }

  public Polynomial(double a, double b, double c, double d, double e) => Set(a, b, c, d, e);

  public Polynomial(double a, double b, double c, double d) => Set(a, b, c, d);

  public Polynomial(double a, double b, double c) => Set(a, b, c);

  public static Polynomial NullPolynomial() => new();

  public void Set(double a, double b, double c, double d, double e) => (n, A, B, C, D, E) = (4, a, b, c, d, e);

  public void Set(double a, double b, double c, double d) => (n, A, B, C, D, E) = (3, a, b, c, d, 0.0);

  public void Set(double a, double b, double c) => (n, A, B, C, D, E) = (2, a, b, c, 0.0, 0.0);

  public static Polynomial operator *(Polynomial u, double e)
  {
    var r = new Polynomial(u);
    r.A *= e;
    r.B *= e;
    r.C *= e;
    r.D *= e;
    r.E *= e;
    return r;
  }

  public static Polynomial operator *(double a, Polynomial p) => p * a;

  public static Polynomial operator /(Polynomial p, double a) => p * (1.0 / a);

  /// <summary>The value at <paramref name="x"/> (Horner).</summary>
  public double Evaluate(double x) => Value(x, E, D);

  double Value(double x, double e, double d) => (((e * x + d) * x + C) * x + B) * x + A;

  /// <summary>Real roots of <c>A + B x + C x²</c> (linear when C is 0).</summary>
  public int SolveQuadratic(double[] y) => Finish(y, Quadratic(A, B, C, y), 2);

  /// <summary>Real roots of <c>A + B x + C x² + D x³</c> (a quadratic when D is negligible).</summary>
  public int SolveCubic(double[] y) => Finish(y, Cubic(A, B, C, D, y), 3);

  /// <summary>Real roots of the quartic (a cubic when E is negligible).</summary>
  public int SolveQuartic(double[] results)
  {
    ArgumentNullException.ThrowIfNull(results);
    int count;
    if (Math.Abs(E) < COEFF_LIMIT)
      count = Cubic(A, B, C, D, results);
    else
    {
      // Depressed quartic x = t − b/4: t⁴ + p t² + q t + r, split by Ferrari's resolvent.
      double b = D / E, c = C / E, d = B / E, e = A / E;
      double bb = b * b;
      double p = c - 0.375 * bb;
      double q = 0.125 * bb * b - 0.5 * b * c + d;
      double r = -0.01171875 * bb * bb + 0.0625 * bb * c - 0.25 * b * d + e;
      double shift = -0.25 * b;
      Span<double> t = stackalloc double[4];
      count = 0;
      if (Math.Abs(q) < EPSILON)
      {
        // Biquadratic: t² = s for the roots s of s² + p s + r.
        double[] s = new double[2];
        int ns = Quadratic(r, p, 1.0, s);
        for (int i = 0; i < ns; i++)
          if (s[i] >= 0.0)
          {
            double root = Math.Sqrt(s[i]);
            t[count++] = root;
            if (root > 0.0)
              t[count++] = -root;
          }
      }
      else
      {
        // m > 0 from 8m³ + 8p m² + (2p² − 8r) m − q² = 0; then two quadratics in t.
        double[] m3 = new double[3];
        int nm = Cubic(-q * q, 2.0 * p * p - 8.0 * r, 8.0 * p, 8.0, m3);
        double m = double.NaN;
        for (int i = 0; i < nm; i++)
          if (m3[i] > 0.0 && !(m >= m3[i]))
            m = m3[i];
        if (m > 0.0)
        {
          double root2m = Math.Sqrt(2.0 * m);
          double[] s = new double[2];
          foreach (int sign in new[] { 1, -1 })
          {
            // t² ∓ √(2m) t + (p/2 + m ± q / (2√(2m))) = 0
            int ns = Quadratic(0.5 * p + m + sign * q / (2.0 * root2m), -sign * root2m, 1.0, s);
            for (int i = 0; i < ns; i++)
              t[count++] = s[i];
          }
        }
      }
      for (int i = 0; i < count; i++)
        results[i] = t[i] + shift;
    }
    return Finish(results, count, 4);
  }

  /// <summary>Newton-polishes (on the terms up to <paramref name="degree"/>), sorts and de-duplicates the first <paramref name="count"/> roots.</summary>
  int Finish(double[] y, int count, int degree)
  {
    double e = degree >= 4 ? E : 0.0, d = degree >= 3 ? D : 0.0;
    for (int i = 0; i < count; i++)
    {
      double x = y[i];
      for (int k = 0; k < 3; k++)
      {
        double f = Value(x, e, d), df = ((4.0 * e * x + 3.0 * d) * x + 2.0 * C) * x + B;
        if (df == 0.0 || !double.IsFinite(f / df))
          break;
        double next = x - f / df;
        if (Math.Abs(Value(next, e, d)) >= Math.Abs(f))
          break;
        x = next;
      }
      y[i] = x;
    }
    Array.Sort(y, 0, count);
    int unique = 0;
    for (int i = 0; i < count; i++)
      if (unique == 0 || Math.Abs(y[i] - y[unique - 1]) > EPSILON * Math.Max(1.0, Math.Abs(y[i])))
        y[unique++] = y[i];
    return unique;
  }

  static int Quadratic(double a, double b, double c, double[] y)
  {
    if (Math.Abs(c) < COEFF_LIMIT)
    {
      if (b == 0.0)
        return 0;
      y[0] = -a / b;
      return 1;
    }
    double disc = b * b - 4.0 * c * a;
    if (disc < 0.0)
      return 0;
    if (disc == 0.0)
    {
      y[0] = -0.5 * b / c;
      return 1;
    }
    // Stable: q = −(b + sign(b)√disc)/2, roots q/c and a/q.
    double q = -0.5 * (b + Math.CopySign(Math.Sqrt(disc), b));
    y[0] = q / c;
    y[1] = q != 0.0 ? a / q : -y[0];
    return 2;
  }

  static int Cubic(double a, double b, double c, double d, double[] y)
  {
    if (Math.Abs(d) < EPSILON * Math.Max(1.0, Math.Max(Math.Abs(c), Math.Max(Math.Abs(b), Math.Abs(a)))))
      return Quadratic(a, b, c, y);
    double a1 = c / d, a2 = b / d, a3 = a / d;
    double q = (a1 * a1 - 3.0 * a2) / 9.0;
    double r = (a1 * (2.0 * a1 * a1 - 9.0 * a2) + 27.0 * a3) / 54.0;
    double q3 = q * q * q;
    double shift = a1 / 3.0;
    if (r * r <= q3)
    {
      // Three real roots (trigonometric form).
      double theta = Math.Acos(Math.Clamp(r / Math.Sqrt(q3), -1.0, 1.0)) / 3.0;
      double s = -2.0 * Math.Sqrt(q);
      y[0] = s * Math.Cos(theta) - shift;
      y[1] = s * Math.Cos(theta + PI_2_3) - shift;
      y[2] = s * Math.Cos(theta + PI_4_3) - shift;
      return 3;
    }
    double u = -Math.CopySign(Math.Cbrt(Math.Abs(r) + Math.Sqrt(r * r - q3)), r);
    double v = u != 0.0 ? q / u : 0.0;
    y[0] = u + v - shift;
    return 1;
  }
}
