using System;
using System.IO;
using BenchmarkDotNet.Attributes;
using Rendering.Imaging;
using StbImageWriteSharp;

namespace GrCis.Bench;

/// <summary>
/// The render's final save: a render-like 8-bit image encoded to PNG in memory by the hand-written
/// encoder (BCL ZLibStream, adaptive filters) and by StbImageWriteSharp. Decides which one
/// <see cref="PngFile.Save(string, Rgb8Image, PngEncoder?)"/> uses (docs/dependencies.md).
/// </summary>
[MemoryDiagnoser]
public class PngSaveBenchmarks
{
  Rgb8Image image = new(1, 1);

  [Params("640x480", "3840x2160")]
  public string Size { get; set; } = "640x480";

  [GlobalSetup]
  public void Setup()
  {
    string[] wh = Size.Split('x');
    image = RenderLike(int.Parse(wh[0]), int.Parse(wh[1]));
  }

  [Benchmark(Baseline = true)]
  public long HandWritten()
  {
    using MemoryStream ms = new();
    PngEncoder.Default.Encode(image, ms);
    return ms.Length;
  }

  [Benchmark]
  public long StbImageWrite()
  {
    using MemoryStream ms = new();
    new ImageWriter().WritePng(image.Data, image.Width, image.Height, ColorComponents.RedGreenBlue, ms);
    return ms.Length;
  }

  /// <summary>Smooth shading, hard edges and a little noise, like a ray-traced frame.</summary>
  static Rgb8Image RenderLike(int w, int h)
  {
    var img = new Rgb8Image(w, h);
    var rnd = new Random(1);
    for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++)
      {
        double dx = x - w * 0.4, dy = y - h * 0.5;
        bool sphere = dx * dx + dy * dy < (h * 0.3) * (h * 0.3);
        int shade = sphere ? (int)(200 - Math.Sqrt(dx * dx + dy * dy) * 200 / (h * 0.3)) : (y * 255 / h);
        int n = rnd.Next(3);
        img.SetPixel(x, y, (byte)Math.Clamp(shade + n, 0, 255), (byte)Math.Clamp(shade / 2 + n, 0, 255), (byte)(sphere ? 40 : 180));
      }
    return img;
  }
}
