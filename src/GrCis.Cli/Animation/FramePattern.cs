using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace GrCis.Cli.Animation;

/// <summary>
/// The <c>-o</c> pattern of <c>grcis animate</c>, Blender's convention: the last run of <c>#</c> in the
/// file name is the zero-padded frame number (as many digits as there are <c>#</c>); a name without
/// <c>#</c> gets four digits before its extension (<c>out.png</c> → <c>out0007.png</c>).
/// </summary>
public sealed class FramePattern
{
  readonly string directory;
  readonly string prefix;
  readonly string suffix;

  FramePattern(string fullPattern, string directory, string prefix, int digits, string suffix)
  {
    FullPattern = fullPattern;
    this.directory = directory;
    this.prefix = prefix;
    Digits = digits;
    this.suffix = suffix;
  }

  /// <summary>The pattern as an absolute path.</summary>
  public string FullPattern { get; }

  /// <summary>Folder the frames go to.</summary>
  public string Directory => directory;

  /// <summary>Minimum number of digits of the frame number.</summary>
  public int Digits { get; }

  /// <exception cref="UsageException">No file name, or not a .png file.</exception>
  public static FramePattern Parse(string pattern, string workingDirectory)
  {
    if (string.IsNullOrWhiteSpace(pattern))
      throw new UsageException("missing output pattern: give -o frames/out####.png");
    string full = Path.GetFullPath(pattern, workingDirectory);
    string name = Path.GetFileName(full);
    string dir = Path.GetDirectoryName(full) ?? workingDirectory;
    if (name.Length == 0)
      throw new UsageException($"output pattern '{pattern}' has no file name; e.g. frames/out####.png");
    if (!Path.GetExtension(name).Equals(".png", StringComparison.OrdinalIgnoreCase))
      throw new UsageException($"output pattern '{pattern}' must end in .png (animation frames are PNG files)");

    int end = name.LastIndexOf('#');
    if (end < 0)
    {
      string stem = Path.GetFileNameWithoutExtension(name);
      return new FramePattern(full, dir, stem, 4, Path.GetExtension(name));
    }
    int start = end;
    while (start > 0 && name[start - 1] == '#')
      start--;
    return new FramePattern(full, dir, name[..start], end - start + 1, name[(end + 1)..]);
  }

  /// <summary>Full path of frame <paramref name="frame"/>.</summary>
  public string FileOf(int frame) =>
    Path.Combine(directory, prefix + frame.ToString("D" + Digits, CultureInfo.InvariantCulture) + suffix);

  /// <summary>The pattern in ffmpeg's image-sequence syntax (<c>out%04d.png</c>, literal '%' doubled).</summary>
  public string FfmpegPattern()
  {
    var sb = new StringBuilder();
    sb.Append(prefix.Replace("%", "%%", StringComparison.Ordinal));
    sb.Append('%').Append('0').Append(Digits.ToString(CultureInfo.InvariantCulture)).Append('d');
    sb.Append(suffix.Replace("%", "%%", StringComparison.Ordinal));
    return Path.Combine(directory, sb.ToString());
  }
}
