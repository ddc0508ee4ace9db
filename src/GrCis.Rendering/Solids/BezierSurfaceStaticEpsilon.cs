namespace Rendering;

/// <summary><c>BezierSurface.Epsilon</c> as GrCis had it until May 2020: a static property (see <see cref="BezierSurface.SharedEpsilon"/>).</summary>
public static class BezierSurfaceStaticEpsilon
{
  extension(BezierSurface)
  {
    /// <summary>Subdivision threshold shared by all Bézier surfaces built afterwards (squared diagonal of a piece's box).</summary>
    public static double Epsilon
    {
      get => BezierSurface.SharedEpsilon;
      set => BezierSurface.SharedEpsilon = value;
    }
  }
}
