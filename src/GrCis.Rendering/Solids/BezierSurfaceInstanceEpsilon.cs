namespace Rendering;

/// <summary><c>surface.Epsilon</c> as GrCis has it since June 2020: an instance property setting the one shared threshold (see <see cref="BezierSurface.SharedEpsilon"/>).</summary>
public static class BezierSurfaceInstanceEpsilon
{
  extension(BezierSurface surface)
  {
    /// <summary>Subdivision threshold shared by all Bézier surfaces built afterwards (squared diagonal of a piece's box).</summary>
    public double Epsilon
    {
      get => BezierSurface.SharedEpsilon;
      set => BezierSurface.SharedEpsilon = value;
    }
  }
}
