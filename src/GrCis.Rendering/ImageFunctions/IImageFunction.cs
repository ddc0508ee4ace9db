namespace Rendering;

/// <summary>The colour of a continuous image point.</summary>
public interface IImageFunction
{
  /// <summary>Width of the image in pixels: <see cref="GetSample"/> takes x in [0, Width]. A ray-based function passes it to the scene's camera.</summary>
  double Width { get; set; }

  /// <summary>Height of the image in pixels: <see cref="GetSample"/> takes y in [0, Height]. A ray-based function passes it to the scene's camera.</summary>
  double Height { get; set; }

  /// <summary>Computes the colour at (x, y) in pixel units; the returned hash changes where objects change.</summary>
  long GetSample(double x, double y, double[] color);
}
