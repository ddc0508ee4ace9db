using System;
using System.Linq;
using MathSupport;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>GrCis's Polynomial (A constant … E quartic) finds the real roots of known polynomials.</summary>
public class PolynomialTests
{
  static double[] Roots(Func<double[], int> solve)
  {
    double[] y = new double[4];
    int n = solve(y);
    return y.Take(n).ToArray();
  }

  static void Near(double[] expected, double[] actual)
  {
    Assert.Equal(expected.Length, actual.Length);
    for (int i = 0; i < expected.Length; i++)
      Assert.Equal(expected[i], actual[i], 9);
  }

  [Fact]
  public void Quadratic_roots_are_the_roots_not_their_reciprocals()
  {
    // (x − 2)(x − 5) = 10 − 7x + x²
    Near(new[] { 2.0, 5.0 }, Roots(new Polynomial(10, -7, 1).SolveQuadratic));
    // 2x² − 8 = 0
    Near(new[] { -2.0, 2.0 }, Roots(new Polynomial(-8, 0, 2).SolveQuadratic));
    // linear 3 + 6x
    Near(new[] { -0.5 }, Roots(new Polynomial(3, 6, 0).SolveQuadratic));
    Assert.Empty(Roots(new Polynomial(1, 0, 1).SolveQuadratic));
    Near(new[] { 3.0 }, Roots(new Polynomial(9, -6, 1).SolveQuadratic));   // double root once
  }

  [Fact]
  public void Cubic_roots()
  {
    // (x + 1)(x − 2)(x − 3) = 6 + x − 4x² + x³
    Near(new[] { -1.0, 2.0, 3.0 }, Roots(new Polynomial(6, 1, -4, 1).SolveCubic));
    // x³ − 8, one real root
    Near(new[] { 2.0 }, Roots(new Polynomial(-8, 0, 0, 1).SolveCubic));
    Near(new[] { 2.0, 5.0 }, Roots((new Polynomial(10, -7, 1, 0) * 3.0).SolveCubic));
  }

  [Fact]
  public void Quartic_roots_including_a_torus_like_case()
  {
    // (x − 1)(x − 2)(x − 3)(x − 4) = 24 − 50x + 35x² − 10x³ + x⁴, scaled by 2
    Near(new[] { 1.0, 2.0, 3.0, 4.0 }, Roots(new Polynomial(48, -100, 70, -20, 2).SolveQuartic));
    // Biquadratic x⁴ − 5x² + 4 = (x² − 1)(x² − 4)
    Near(new[] { -2.0, -1.0, 1.0, 2.0 }, Roots(new Polynomial(4, 0, -5, 0, 1).SolveQuartic));
    // (x² + 1)(x − 0.5)(x − 7): two real roots
    var p = new Polynomial(3.5, -7.5, 4.5, -7.5, 1);
    Near(new[] { 0.5, 7.0 }, Roots(p.SolveQuartic));
    Assert.Empty(Roots(new Polynomial(1, 0, 2, 0, 1).SolveQuartic));        // (x² + 1)²
    Assert.Equal(0.0, p.Evaluate(7.0), 9);
  }
}
