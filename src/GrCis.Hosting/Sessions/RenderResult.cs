using System;
using System.Collections.Generic;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Hosting;

/// <summary>
/// The outcome of a render session: the rendered frame (<see cref="FrameResult"/>, the result type of every
/// front end), the job it was rendered for, the tiles that finished, and what went wrong, if anything.
/// </summary>
public sealed class RenderResult
{
  internal RenderResult(RenderJob job, FrameResult frame, IReadOnlyList<Tile> finishedTiles, Exception? error)
  {
    Job = job;
    Frame = frame;
    FinishedTiles = finishedTiles;
    Error = error;
  }

  public RenderJob Job { get; }

  /// <summary>The image, its statistics and whether it was stopped.</summary>
  public FrameResult Frame { get; }

  /// <summary>Linear colours. After a stop, finished tiles are exact and the rest is black.</summary>
  public FloatImage Image => Frame.Image;

  public RenderStatistics Statistics => Frame.Statistics;

  public IReadOnlyList<Tile> FinishedTiles { get; }

  public bool Cancelled => Frame.Cancelled;

  /// <summary>What went wrong inside the scene, or null.</summary>
  public Exception? Error { get; }

  public bool Succeeded => !Cancelled && Error == null;

  /// <summary>Display gamma of the renderer; used to show and save the image.</summary>
  public double Gamma => Job.Renderer.Gamma;

  /// <summary>The 8-bit display image (gamma applied, quantized as <c>grcis render</c> saves it).</summary>
  public Rgb8Image ToRgb8() => Rendering.Execution.RenderSetup.ToDisplayImage(Image, Gamma);
}
