using GrCis.Hosting;

namespace GrCis.Cli.Jobs;

/// <summary>
/// Refuses, before any work, an image size whose buffers do not fit in the memory this process may use
/// (<see cref="ImageMemory"/>, the check every front end makes), as a failure of the command.
/// </summary>
internal static class MemoryBudget
{
  public const long BytesPerPixel = ImageMemory.BytesPerPixel;

  public const long Baseline = ImageMemory.Baseline;

  public static long Needed(ImageSize size, int imagesAtOnce = 1) => ImageMemory.Needed(size.Width, size.Height, imagesAtOnce);

  /// <exception cref="CliFailure">The size needs more than <paramref name="available"/> bytes.</exception>
  public static void Check(ImageSize size, int imagesAtOnce = 1, long? available = null)
  {
    if (ImageMemory.Shortfall(size.Width, size.Height, imagesAtOnce, available) is string shortfall)
      throw new CliFailure(shortfall + "; render a smaller --size");
  }
}
