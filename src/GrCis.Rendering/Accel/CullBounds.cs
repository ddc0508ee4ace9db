using System;

namespace Rendering.Accel;

/// <summary>Bounds the culls may take instead of exact quotients: they only decide what is tested, never an answer.</summary>
internal static class CullBounds
{
  /// <summary>
  /// An upper bound on 1/√<paramref name="x"/> (x = |d|²) at most ~2 % above it, from the processor's single-precision
  /// estimate (relative error below 2⁻¹¹ on x86, 2⁻⁸ on ARM) raised by 1 %: no square root or division, whose unit the
  /// query's own roots wait for. Outside single precision's comfortable range the exact quotient.
  /// </summary>
  public static double UpperInverseLength(double x)
  {
    if (x > 1.0e-30 && x < 1.0e30)
      return 1.01 * MathF.ReciprocalSqrtEstimate((float)x);
    return 1.0 / Math.Sqrt(x);
  }
}
