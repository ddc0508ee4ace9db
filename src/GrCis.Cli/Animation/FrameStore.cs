using System;
using System.IO;
using GrCis.Cli.Jobs;
using Rendering.Imaging;

namespace GrCis.Cli.Animation;

/// <summary>
/// The frame files of an animation on disk. A frame is written under a temporary sibling name and
/// renamed when complete (<see cref="PngFile.Save(string, Rgb8Image, PngEncoder?)"/>), so a killed
/// process leaves whole frames and, at worst, temporary files, which the next run removes.
/// </summary>
public sealed class FrameStore
{
  readonly FramePattern pattern;
  readonly ImageSize size;
  readonly double gamma;

  public FrameStore(FramePattern pattern, ImageSize size, double gamma)
  {
    this.pattern = pattern;
    this.size = size;
    this.gamma = gamma;
  }

  public FramePattern Pattern => pattern;

  /// <summary>Creates the frame folder if needed and proves it writable before any frame is rendered.</summary>
  /// <exception cref="CliFailure">The folder cannot be created or written.</exception>
  public void Prepare()
  {
    string dir = pattern.Directory;
    try
    {
      if (File.Exists(dir))
        throw new CliFailure($"cannot write frames to '{dir}': it is a file");
      Directory.CreateDirectory(dir);
      string probe = Path.Combine(dir, ".grcis-probe-" + Guid.NewGuid().ToString("N")[..12]);
      using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose))
      {
      }
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      throw new CliFailure($"cannot write frames to '{dir}': {(e is UnauthorizedAccessException ? "permission denied" : e.Message)}", e);
    }
  }

  /// <summary>
  /// True when frame <paramref name="frame"/> is done: its final file exists, decodes as a PNG and
  /// has the size being rendered (a frame left from a run at another size is rendered again).
  /// </summary>
  public bool IsComplete(int frame)
  {
    string file = pattern.FileOf(frame);
    if (!File.Exists(file))
      return false;
    try
    {
      Rgb8Image image = PngFile.Load(file);
      return image.Width == size.Width && image.Height == size.Height;
    }
    catch (Exception e) when (e is not OutOfMemoryException)
    {
      // Whatever a damaged file makes the decoder throw, the frame is not complete: render it again.
      return false;
    }
  }

  /// <summary>Deletes temporary files a killed run left for this frame; returns how many.</summary>
  public int RemoveStaleTemporaries(int frame)
  {
    string file = pattern.FileOf(frame);
    string? dir = Path.GetDirectoryName(file);
    if (dir == null || !Directory.Exists(dir))
      return 0;
    int removed = 0;
    foreach (string temp in Directory.EnumerateFiles(dir, Path.GetFileName(file) + ".tmp-*"))
    {
      try
      {
        File.Delete(temp);
        removed++;
      }
      catch (Exception e) when (e is IOException or UnauthorizedAccessException)
      {
        // Left for the next run; the frame itself is still written atomically.
      }
    }
    return removed;
  }

  /// <summary>Writes frame <paramref name="frame"/> atomically, with the render display encoding (<see cref="DisplayEncoding.ForRender"/>).</summary>
  /// <exception cref="CliFailure">The frame could not be written; no partial file remains.</exception>
  public void Save(int frame, FloatImage image)
  {
    string file = pattern.FileOf(frame);
    try
    {
      PngFile.Save(file, DisplayEncoding.ForRender(gamma).Encode(image));
    }
    catch (ImageSaveException e)
    {
      Exception reason = e.InnerException ?? e;
      throw new CliFailure($"cannot write '{file}': {(reason is UnauthorizedAccessException ? "permission denied" : reason.Message)}", e);
    }
  }
}
