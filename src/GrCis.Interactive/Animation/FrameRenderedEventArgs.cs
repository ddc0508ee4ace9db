using System;
using Rendering.Imaging;

namespace GrCis.Interactive;

/// <summary>An animation frame is done; carries the image and the estimate of the time left.</summary>
public sealed class FrameRenderedEventArgs : EventArgs
{
  public FrameRenderedEventArgs(int frame, double time, FloatImage image, int framesDone, int framesTotal, TimeSpan elapsed, string? file)
  {
    Frame = frame;
    Time = time;
    Image = image;
    FramesDone = framesDone;
    FramesTotal = framesTotal;
    Elapsed = elapsed;
    File = file;
  }

  public int Frame { get; }

  /// <summary>Scene time of the frame.</summary>
  public double Time { get; }

  public FloatImage Image { get; }

  public int FramesDone { get; }

  public int FramesTotal { get; }

  public TimeSpan Elapsed { get; }

  /// <summary>Where the frame was saved, if a pattern was given.</summary>
  public string? File { get; }

  /// <summary>Estimated time left: mean frame time so far times the frames still to render.</summary>
  public TimeSpan Eta => FramesDone == 0 ? TimeSpan.Zero : Elapsed / FramesDone * (FramesTotal - FramesDone);
}
