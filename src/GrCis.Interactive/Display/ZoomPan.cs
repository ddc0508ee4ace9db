using System;

namespace GrCis.Interactive;

/// <summary>
/// Zoom and pan of the image in its view, as the demo does it: the wheel zooms about the cursor,
/// right-drag pans, +/− zoom about the view centre, R resets. Screen = image · <see cref="Zoom"/> + offset.
/// </summary>
public sealed class ZoomPan
{
  public const double MinZoom = 1.0 / 8.0;
  public const double MaxZoom = 64.0;

  /// <summary>Zoom factor of one wheel notch or one +/− key press.</summary>
  public const double Step = 1.25;

  /// <summary>Screen pixels per image pixel.</summary>
  public double Zoom { get; private set; } = 1.0;

  /// <summary>Screen position of the image's top-left corner.</summary>
  public double OffsetX { get; private set; }

  public double OffsetY { get; private set; }

  public event EventHandler? Changed;

  /// <summary>Multiplies the zoom by <paramref name="factor"/> keeping the image point under (<paramref name="sx"/>, <paramref name="sy"/>) in place.</summary>
  public void ZoomAt(double sx, double sy, double factor)
  {
    if (!(factor > 0.0) || double.IsInfinity(factor))
      throw new ArgumentOutOfRangeException(nameof(factor), factor, "The zoom factor must be a positive number.");
    double zoom = Math.Clamp(Zoom * factor, MinZoom, MaxZoom);
    (double ix, double iy) = ToImage(sx, sy);
    OffsetX = sx - ix * zoom;
    OffsetY = sy - iy * zoom;
    Zoom = zoom;
    Changed?.Invoke(this, EventArgs.Empty);
  }

  /// <summary>One wheel event: positive <paramref name="notches"/> zoom in.</summary>
  public void Wheel(double sx, double sy, double notches) => ZoomAt(sx, sy, Math.Pow(Step, notches));

  public void Pan(double dx, double dy)
  {
    OffsetX += dx;
    OffsetY += dy;
    Changed?.Invoke(this, EventArgs.Empty);
  }

  /// <summary>Zoom 1, image in the top-left corner.</summary>
  public void Reset()
  {
    Zoom = 1.0;
    OffsetX = OffsetY = 0.0;
    Changed?.Invoke(this, EventArgs.Empty);
  }

  /// <summary>The image coordinates under a screen point.</summary>
  public (double X, double Y) ToImage(double sx, double sy) => ((sx - OffsetX) / Zoom, (sy - OffsetY) / Zoom);

  /// <summary>The screen rectangle the image of the given size covers.</summary>
  public (double X, double Y, double Width, double Height) ImageBounds(int width, int height) =>
    (OffsetX, OffsetY, width * Zoom, height * Zoom);

  /// <summary>The pixel under a screen point; false outside an image of the given size.</summary>
  public bool TryPixelAt(double sx, double sy, int width, int height, out int x, out int y)
  {
    (double ix, double iy) = ToImage(sx, sy);
    x = (int)Math.Floor(ix);
    y = (int)Math.Floor(iy);
    return ix >= 0.0 && iy >= 0.0 && x < width && y < height;
  }
}
