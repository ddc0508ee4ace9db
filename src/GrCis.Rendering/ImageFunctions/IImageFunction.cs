namespace Rendering;

/// <summary>The colour of a continuous image point.</summary>
public interface IImageFunction
{
  double Width { get; set; }

  double Height { get; set; }

  /// <summary>Computes the colour at (x, y) in pixel units; the returned hash changes where objects change.</summary>
  long GetSample(double x, double y, double[] color);
}
