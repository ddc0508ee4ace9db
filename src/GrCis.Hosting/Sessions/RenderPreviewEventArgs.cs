using System;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>A preview image: a snapshot the receiver owns (linear colours).</summary>
public sealed class RenderPreviewEventArgs : EventArgs
{
  public RenderPreviewEventArgs(FloatImage image, PreviewPass pass, double fraction, int sequence, double gamma)
  {
    Image = image;
    Pass = pass;
    Fraction = fraction;
    Sequence = sequence;
    Gamma = gamma;
  }

  public FloatImage Image { get; }

  public PreviewPass Pass { get; }

  /// <summary>Fraction of the render's work finished (tiles, or samples of a progressive render).</summary>
  public double Fraction { get; }

  /// <summary>0, 1, 2, … in the order the previews were made.</summary>
  public int Sequence { get; }

  public double Gamma { get; }

  /// <summary>Samples every pixel has so far in a progressive render (<see cref="PreviewPass.Samples"/>); else null.</summary>
  public int? Samples { get; init; }

  /// <summary>The estimated noise (RMSE) of the image on show, when known (<see cref="RenderStatistics.Noise"/>).</summary>
  public double? Noise { get; init; }

  public Rgb8Image ToRgb8() => Rendering.Execution.RenderSetup.ToDisplayImage(Image, Gamma);
}
