using System;
using System.IO;
using GrCis.Cli.Jobs;
using Rendering.Imaging;

namespace GrCis.Cli.Animation;

/// <summary>
/// The frame files of an animation on disk. A frame is written under a temporary sibling name and
/// renamed when complete (<see cref="PngFile.Save(string, Rgb8Image, PngEncoder?)"/>), so a killed
/// process leaves whole frames and, at worst, temporary files, which the next run removes. Every frame
/// carries its <see cref="FrameFingerprint"/>, which <see cref="Check"/> verifies for <c>--resume</c>.
/// </summary>
public sealed class FrameStore
{
  readonly FramePattern pattern;
  readonly ImageSize size;
  readonly double gamma;
  readonly FrameFingerprint fingerprint;

  public FrameStore(FramePattern pattern, ImageSize size, double gamma, FrameFingerprint fingerprint)
  {
    ArgumentNullException.ThrowIfNull(fingerprint);
    this.pattern = pattern;
    this.size = size;
    this.gamma = gamma;
    this.fingerprint = fingerprint;
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

  /// <summary>True when frame <paramref name="frame"/> is done: <see cref="Check"/> keeps it.</summary>
  public bool IsComplete(int frame) => Check(frame).State == FrameState.Kept;

  /// <summary>
  /// Whether frame <paramref name="frame"/>'s file is a whole frame of this render: every chunk's CRC and
  /// the image data's zlib checksum hold (<see cref="CheckedPng"/>), its fingerprint equals this render's
  /// for that frame, and the decoded pixels match the checksum in it. Anything else is rendered again.
  /// </summary>
  public FrameCheck Check(int frame)
  {
    string file = pattern.FileOf(frame);
    if (!File.Exists(file))
      return FrameCheck.Missing;
    try
    {
      // Judged by its length before it is opened: a FIFO (length 0) would wait for a writer, and a
      // huge file is no frame of this size. Deflate adds at most a few bytes per 16 KiB block.
      long length = new FileInfo(file).Length;
      long raw = (long)size.Height * (1 + 3L * size.Width);
      long max = raw + raw / 256 + (1 << 20);
      if (length < MinPngLength)
        return new FrameCheck(FrameState.Corrupt, length == 0 ? "empty" : $"cut off ({length} bytes)");
      if (length > max)
        return new FrameCheck(FrameState.Corrupt, $"{length} bytes, more than a {size} frame takes");

      CheckedPng png = CheckedPng.Read(file, max);
      if (!png.Text.TryGetValue(FrameFingerprint.Keyword, out string? stored))
        return new FrameCheck(FrameState.NoFingerprint);
      FrameCheck verdict = fingerprint.Compare(frame, stored, out string pixels);
      if (verdict.State != FrameState.Kept)
        return verdict;
      Rgb8Image image = png.Decode();
      if (image.Width != size.Width || image.Height != size.Height)
        return new FrameCheck(FrameState.Corrupt, $"{image.Width}x{image.Height} pixels where its fingerprint says {size}");
      if (FrameFingerprint.PixelHash(image) != pixels)
        return new FrameCheck(FrameState.Corrupt, "its pixels do not match their checksum");
      return FrameCheck.Kept;
    }
    catch (InvalidDataException e)
    {
      return new FrameCheck(FrameState.Corrupt, Reason(e.Message, file));
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      return new FrameCheck(FrameState.Corrupt, $"unreadable ({(e is UnauthorizedAccessException ? "permission denied" : e.Message)})");
    }
  }

  // Signature, IHDR, an IDAT and IEND: no PNG is shorter.
  const long MinPngLength = 8 + 25 + 12 + 12;

  /// <summary>The reader's message without the path it starts with (the report names the file).</summary>
  static string Reason(string message, string file) =>
    message.StartsWith(file + ": ", StringComparison.Ordinal) ? message[(file.Length + 2)..] : message;

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

  /// <summary>
  /// Writes frame <paramref name="frame"/> atomically, with the render display encoding (<see cref="DisplayEncoding.ForRender"/>)
  /// and its fingerprint.
  /// </summary>
  /// <exception cref="CliFailure">The frame could not be written; no partial file remains.</exception>
  public void Save(int frame, FloatImage image)
  {
    string file = pattern.FileOf(frame);
    try
    {
      Rgb8Image pixels = DisplayEncoding.ForRender(gamma).Encode(image);
      PngFile.Save(file, pixels, fingerprint.Entries(frame, pixels));
    }
    catch (ImageSaveException e)
    {
      Exception reason = e.InnerException ?? e;
      throw new CliFailure($"cannot write '{file}': {(reason is UnauthorizedAccessException ? "permission denied" : reason.Message)}", e);
    }
  }
}
