using System;
using System.IO;
using Rendering.Imaging;
using Rendering.Parts;

namespace GrCis.Cli.Output;

/// <summary>
/// The file a render goes to. Checked before rendering (so a long render does not fail at the end)
/// and written atomically (temporary sibling, then rename): a failed or interrupted save leaves no
/// file behind and never a half-written one.
/// </summary>
public sealed class OutputTarget
{
  public OutputTarget(string fullPath, OutputFormat format)
  {
    FullPath = fullPath;
    Format = format;
  }

  public string FullPath { get; }

  public OutputFormat Format { get; }

  /// <summary>
  /// Resolves <c>-o</c> and <c>--format</c>: without <c>-o</c> the file is <c>{stem}.png</c> (or .pfm)
  /// in <paramref name="workingDirectory"/>; without <c>--format</c> the extension decides.
  /// </summary>
  /// <param name="option">The option that gave <paramref name="output"/>, for messages.</param>
  /// <exception cref="UsageException">Unknown format or extension, or an empty file name.</exception>
  public static OutputTarget Resolve(string? output, string? format, string defaultStem, string workingDirectory, string option = "-o")
  {
    OutputFormat? explicitFormat = format == null ? null : ParseFormat(format);
    // An empty name is a mistake (an unset shell variable), not a request for the default name.
    if (output != null && string.IsNullOrWhiteSpace(output))
      throw new UsageException($"{option} needs a file name (got an empty one); leave {option} out for the default name");
    if (output == null)
    {
      OutputFormat f = explicitFormat ?? OutputFormat.Png;
      return new OutputTarget(Path.Combine(workingDirectory, defaultStem + Extension(f)), f);
    }

    string full = Path.GetFullPath(output, workingDirectory);
    if (explicitFormat is OutputFormat given)
      return new OutputTarget(full, given);
    string ext = Path.GetExtension(full).ToLowerInvariant();
    return ext switch
    {
      ".png" => new OutputTarget(full, OutputFormat.Png),
      ".pfm" => new OutputTarget(full, OutputFormat.Pfm),
      PartFile.Extension => new OutputTarget(full, OutputFormat.Part),
      "" => throw new UsageException($"output file '{output}' has no extension; use .png or .pfm (or --format)"),
      _ => throw new UsageException($"cannot write '{ext}' files ('{output}'); use .png or .pfm (or --format)"),
    };
  }

  static OutputFormat ParseFormat(string format) => format.Trim().ToLowerInvariant() switch
  {
    "png" => OutputFormat.Png,
    "pfm" => OutputFormat.Pfm,
    _ => throw new UsageException($"unknown --format '{format}'; use png or pfm"),
  };

  static string Extension(OutputFormat f) => f == OutputFormat.Pfm ? ".pfm" : ".png";

  /// <summary>
  /// Fails early when the file cannot be written: a directory or a device in the way, a file where a folder
  /// should be, no permission. Missing folders are fine: <see cref="Save"/> creates them, as <c>animate</c>
  /// creates its frames folder, so nothing is created when the render fails.
  /// </summary>
  /// <exception cref="CliFailure">The file could not be created; nothing is left behind.</exception>
  public void CheckWritable()
  {
    if (Directory.Exists(FullPath))
      throw new CliFailure($"cannot write '{FullPath}': it is a directory");
    if (IsDevice(FullPath))
      throw new CliFailure($"cannot write '{FullPath}': it is a device, not a file (images are saved through a temporary file and a rename, which would replace it)");
    string? dir = Path.GetDirectoryName(FullPath);
    if (string.IsNullOrEmpty(dir))
      throw new CliFailure($"cannot write '{FullPath}': it has no directory");

    // The nearest folder that exists: a missing one below it is created at save time.
    string existing = dir;
    while (!Directory.Exists(existing))
    {
      if (File.Exists(existing))
        throw new CliFailure($"cannot write '{FullPath}': '{existing}' is a file, not a directory");
      string? parent = Path.GetDirectoryName(existing);
      if (string.IsNullOrEmpty(parent))
        throw new CliFailure($"cannot write '{FullPath}': directory '{dir}' cannot be created");
      existing = parent;
    }

    // Probe with the same kind of sibling file the atomic save creates, and remove it at once.
    string probe = Path.Combine(existing, "." + Path.GetFileName(FullPath) + ".probe-" + Guid.NewGuid().ToString("N")[..12]);
    try
    {
      using var fs = new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      throw new CliFailure($"cannot write '{FullPath}': {Reason(e)}", e);
    }
    finally
    {
      TryDelete(probe);
    }
  }

  /// <summary>
  /// A path in /dev or /proc, or a link to one (/dev/null, /dev/stdout): .NET cannot tell a device from a
  /// file, and as root the atomic rename would put a regular file in the device's place.
  /// </summary>
  static bool IsDevice(string path)
  {
    if (OperatingSystem.IsWindows())
      return false;
    string target = path;
    try
    {
      if (new FileInfo(path).ResolveLinkTarget(returnFinalTarget: true) is FileSystemInfo final)
        target = final.FullName;
    }
    catch (IOException)
    {
      // A broken or looping link: judge the path itself.
    }
    return target.StartsWith("/dev/", StringComparison.Ordinal) || target.StartsWith("/proc/", StringComparison.Ordinal);
  }

  /// <summary>Writes the image: PNG with the render display encoding (<see cref="DisplayEncoding.ForRender"/>), or linear PFM.</summary>
  /// <exception cref="CliFailure">The save failed; any existing file is unchanged and no temporary file remains.</exception>
  public void Save(FloatImage image, double gamma) => Saving(() =>
  {
    if (Format == OutputFormat.Pfm)
      PfmWriter.Save(FullPath, image);
    else
      PngFile.Save(FullPath, DisplayEncoding.ForRender(gamma).Encode(image));
  });

  /// <summary>Writes the tiles of one part (<c>render --tiles</c>) with its header.</summary>
  /// <exception cref="CliFailure">The save failed; any existing file is unchanged and no temporary file remains.</exception>
  public void SavePart(PartHeader header, FloatImage image) => Saving(() => PartFile.Save(FullPath, header, image));

  void Saving(Action save)
  {
    try
    {
      Directory.CreateDirectory(Path.GetDirectoryName(FullPath)!);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      throw new CliFailure($"cannot write '{FullPath}': cannot create its directory: {Reason(e)}", e);
    }
    try
    {
      save();
    }
    catch (ImageSaveException e)
    {
      throw new CliFailure($"cannot write '{FullPath}': {Reason(e.InnerException ?? e)}", e);
    }
  }

  static string Reason(Exception e) => e switch
  {
    UnauthorizedAccessException => "permission denied",
    _ => e.Message,
  };

  static void TryDelete(string path)
  {
    try
    {
      if (File.Exists(path))
        File.Delete(path);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      // Best effort: DeleteOnClose normally removed it already.
    }
  }
}
