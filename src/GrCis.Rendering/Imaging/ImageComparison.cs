using System;

namespace Rendering.Imaging;

/// <summary>Metrics and a visual diff for golden-image tests on 8-bit RGB images of equal size.</summary>
public static class ImageComparison
{
  /// <summary>Mean squared error over all pixels and all three channels.</summary>
  public static double MeanSquaredError(Rgb8Image a, Rgb8Image b)
  {
    CheckSameSize(a, b);
    byte[] da = a.Data, db = b.Data;
    long sum = 0;
    for (int i = 0; i < da.Length; i++)
    {
      int d = da[i] - db[i];
      sum += d * d;
    }
    return (double)sum / da.Length;
  }

  /// <summary>Peak signal-to-noise ratio in dB with peak 255; identical images give +infinity.</summary>
  public static double Psnr(Rgb8Image a, Rgb8Image b)
  {
    double mse = MeanSquaredError(a, b);
    return mse == 0.0 ? double.PositiveInfinity : 10.0 * Math.Log10(255.0 * 255.0 / mse);
  }

  /// <summary>Largest absolute difference of any single channel, 0..255.</summary>
  public static int MaxChannelDifference(Rgb8Image a, Rgb8Image b)
  {
    CheckSameSize(a, b);
    byte[] da = a.Data, db = b.Data;
    int max = 0;
    for (int i = 0; i < da.Length; i++)
      max = Math.Max(max, Math.Abs(da[i] - db[i]));
    return max;
  }

  /// <summary>Per-channel |a - b| stretched so the largest difference becomes 255 (all black when identical).</summary>
  public static Rgb8Image Difference(Rgb8Image a, Rgb8Image b)
  {
    int max = MaxChannelDifference(a, b);
    return DifferenceCore(a, b, max == 0 ? 1.0 : 255.0 / max);
  }

  /// <summary>Per-channel |a - b| * <paramref name="gain"/>, clamped to 255.</summary>
  public static Rgb8Image Difference(Rgb8Image a, Rgb8Image b, int gain)
  {
    if (gain < 1)
      throw new ArgumentOutOfRangeException(nameof(gain), gain, "Gain must be at least 1.");
    CheckSameSize(a, b);
    return DifferenceCore(a, b, gain);
  }

  /// <summary>Saves the stretched difference image as PNG, e.g. next to a failed golden test's output.</summary>
  /// <exception cref="ImageSaveException">The file could not be written.</exception>
  public static void SaveDifference(string path, Rgb8Image a, Rgb8Image b) =>
    PngFile.Save(path, Difference(a, b));

  private static Rgb8Image DifferenceCore(Rgb8Image a, Rgb8Image b, double scale)
  {
    Rgb8Image diff = new(a.Width, a.Height);
    byte[] da = a.Data, db = b.Data, dd = diff.Data;
    for (int i = 0; i < da.Length; i++)
      dd[i] = (byte)Math.Min(255, (int)(Math.Abs(da[i] - db[i]) * scale + 0.5));
    return diff;
  }

  private static void CheckSameSize(Rgb8Image a, Rgb8Image b)
  {
    ArgumentNullException.ThrowIfNull(a);
    ArgumentNullException.ThrowIfNull(b);
    if (a.Width != b.Width || a.Height != b.Height)
      throw new ArgumentException($"Images differ in size: {a.Width}x{a.Height} vs {b.Width}x{b.Height}.");
  }
}
