using System;
using System.IO;
using Rendering.Imaging;
using StbImageWriteSharp;

namespace GrCis.Bench;

/// <summary><c>dotnet run -c Release -- pngsize FILE.png…</c>: PNG size of each image from the hand-written encoder and from StbImageWriteSharp.</summary>
public static class PngSizes
{
  public static int Run(string[] files)
  {
    foreach (string f in files)
    {
      Rgb8Image img = PngFile.Load(f);
      using MemoryStream ours = new(), stb = new();
      PngEncoder.Default.Encode(img, ours);
      new ImageWriter().WritePng(img.Data, img.Width, img.Height, ColorComponents.RedGreenBlue, stb);
      Console.WriteLine($"| {Path.GetFileName(f)} | {img.Width}x{img.Height} | {ours.Length} | {stb.Length} | {(double)stb.Length / ours.Length:0.00} |");
    }
    return 0;
  }
}
