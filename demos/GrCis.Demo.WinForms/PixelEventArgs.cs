using System;

namespace GrCis.Demo.WinForms;

/// <summary>A pixel of the shown image (image coordinates, not screen).</summary>
sealed class PixelEventArgs : EventArgs
{
  public PixelEventArgs(int x, int y)
  {
    X = x;
    Y = y;
  }

  public int X { get; }

  public int Y { get; }
}
