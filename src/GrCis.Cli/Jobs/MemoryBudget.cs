using System;
using System.Globalization;

namespace GrCis.Cli.Jobs;

/// <summary>
/// Refuses, before any work, an image size whose buffers do not fit in the memory this process may use
/// (the machine's RAM, a container's limit or <c>DOTNET_GCHeapHardLimit</c>: what the GC reports as available),
/// instead of failing with an out-of-memory crash after minutes of rendering.
/// </summary>
internal static class MemoryBudget
{
  /// <summary>
  /// Managed bytes per pixel held at the peak of a still: the linear float framebuffer (12), the 8-bit
  /// image (3) and the encoder's rows, rounded up. Measured: a 5600x5600 render fits in a 512 MiB heap.
  /// </summary>
  public const long BytesPerPixel = 16;

  /// <summary>The runtime, the scene and the script compiler besides the image.</summary>
  public const long Baseline = 128L << 20;

  public static long Needed(ImageSize size, int imagesAtOnce = 1) =>
    Baseline + (long)size.Width * size.Height * BytesPerPixel * Math.Max(1, imagesAtOnce);

  /// <summary>Memory this process may use, as the GC sees it.</summary>
  public static long Available => GC.GetGCMemoryInfo().TotalAvailableMemoryBytes;

  /// <exception cref="CliFailure">The size needs more than <paramref name="available"/> bytes.</exception>
  public static void Check(ImageSize size, int imagesAtOnce = 1, long? available = null)
  {
    long need = Needed(size, imagesAtOnce), have = available ?? Available;
    if (need <= have)
      return;
    string images = imagesAtOnce > 1 ? $"{imagesAtOnce} images of {size} at once" : $"a {size} image";
    throw new CliFailure($"{images} needs about {Format(need)} of memory, but this process can use {Format(have)}; render a smaller --size");
  }

  static string Format(long bytes) => bytes >= 1L << 30
    ? string.Create(CultureInfo.InvariantCulture, $"{bytes / (double)(1L << 30):0.0} GiB")
    : string.Create(CultureInfo.InvariantCulture, $"{bytes / (double)(1L << 20):0} MiB");
}
