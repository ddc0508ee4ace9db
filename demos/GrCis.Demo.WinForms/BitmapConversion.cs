using System;
using System.Drawing;
using System.Drawing.Imaging;
using System.Runtime.InteropServices;
using Rendering.Imaging;

namespace GrCis.Demo.WinForms;

/// <summary>The library's 8-bit RGB image as a GDI+ bitmap (24 bpp, rows padded, BGR byte order).</summary>
static class BitmapConversion
{
  public static Bitmap ToBitmap(Rgb8Image image)
  {
    ArgumentNullException.ThrowIfNull(image);
    var bmp = new Bitmap(image.Width, image.Height, PixelFormat.Format24bppRgb);
    BitmapData data = bmp.LockBits(new Rectangle(0, 0, image.Width, image.Height), ImageLockMode.WriteOnly, PixelFormat.Format24bppRgb);
    try
    {
      byte[] row = new byte[data.Stride];
      byte[] src = image.Data;
      for (int y = 0; y < image.Height; y++)
      {
        int s = y * image.Stride;
        for (int x = 0; x < image.Width; x++, s += 3)
        {
          row[3 * x] = src[s + 2];
          row[3 * x + 1] = src[s + 1];
          row[3 * x + 2] = src[s];
        }
        Marshal.Copy(row, 0, IntPtr.Add(data.Scan0, y * data.Stride), data.Stride);
      }
    }
    finally
    {
      bmp.UnlockBits(data);
    }
    return bmp;
  }
}
