using System;
using System.Collections.Generic;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>The outcome of a render session: the image (linear), statistics, and how it ended.</summary>
public sealed class RenderResult
{
  internal RenderResult(RenderJob job, FloatImage image, RenderStatistics statistics, IReadOnlyList<Tile> finishedTiles, bool cancelled, Exception? error)
  {
    Job = job;
    Image = image;
    Statistics = statistics;
    FinishedTiles = finishedTiles;
    Cancelled = cancelled;
    Error = error;
  }

  public RenderJob Job { get; }

  /// <summary>Linear colours. After a stop, finished tiles are exact and the rest is black.</summary>
  public FloatImage Image { get; }

  public RenderStatistics Statistics { get; }

  public IReadOnlyList<Tile> FinishedTiles { get; }

  public bool Cancelled { get; }

  /// <summary>What went wrong inside the scene, or null.</summary>
  public Exception? Error { get; }

  public bool Succeeded => !Cancelled && Error == null;

  /// <summary>Display gamma of the renderer; used to show and save the image.</summary>
  public double Gamma => Job.Renderer.Gamma;

  /// <summary>The 8-bit display image (gamma applied, quantized as <c>grcis render</c> saves it).</summary>
  public Rgb8Image ToRgb8() => Rendering.Execution.RenderSetup.ToDisplayImage(Image, Gamma);
}
