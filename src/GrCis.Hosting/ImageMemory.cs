using System;
using System.Globalization;

namespace GrCis.Hosting;

/// <summary>
/// Whether an image size fits in the memory this process may use (the machine's RAM, a container's limit or
/// <c>DOTNET_GCHeapHardLimit</c>: what the GC reports as available), checked by every front end before any work,
/// instead of an out-of-memory crash (or a machine brought to its knees) after minutes of rendering.
/// </summary>
public static class ImageMemory
{
  /// <summary>
  /// Managed bytes per pixel held at the peak of a still: the linear float framebuffer (12), the 8-bit
  /// image (3) and the encoder's rows, rounded up. Measured: a 5600x5600 render fits in a 512 MiB heap.
  /// </summary>
  public const long BytesPerPixel = 16;

  /// <summary>The runtime, the scene and the script compiler besides the image.</summary>
  public const long Baseline = 128L << 20;

  /// <summary>Bytes needed for <paramref name="imagesAtOnce"/> images of <paramref name="width"/> × <paramref name="height"/>.</summary>
  public static long Needed(int width, int height, int imagesAtOnce = 1) =>
    Baseline + (long)width * height * BytesPerPixel * Math.Max(1, imagesAtOnce);

  /// <summary>Memory this process may use, as the GC sees it.</summary>
  public static long Available => GC.GetGCMemoryInfo().TotalAvailableMemoryBytes;

  /// <summary>Null when the images fit; else what they need and what there is, in words (the front end adds its advice).</summary>
  /// <param name="oneImage">Word it as one image (a window's render, whose previews count as further images).</param>
  public static string? Shortfall(int width, int height, int imagesAtOnce = 1, long? available = null, bool oneImage = false)
  {
    long need = Needed(width, height, imagesAtOnce), have = available ?? Available;
    if (need <= have)
      return null;
    string images = imagesAtOnce > 1 && !oneImage ? $"{imagesAtOnce} images of {width}x{height} at once" : $"a {width}x{height} image";
    return $"{images} needs about {Format(need)} of memory, but this process can use {Format(have)}";
  }

  static string Format(long bytes) => bytes >= 1L << 30
    ? string.Create(CultureInfo.InvariantCulture, $"{bytes / (double)(1L << 30):0.0} GiB")
    : string.Create(CultureInfo.InvariantCulture, $"{bytes / (double)(1L << 20):0} MiB");
}
