using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace GrCis.Cli.Animation;

/// <summary>
/// Encodes a run of frame files into a video with ffmpeg, run as a process: H.264 (libx264,
/// yuv420p, odd sizes padded to even) at the animation's frame rate, falling back to MPEG-4 part 2
/// when ffmpeg has no libx264. The video is written under a temporary name and renamed.
/// </summary>
public sealed class VideoEncoder
{
  /// <summary>Environment variable naming the ffmpeg executable (a path or a command on PATH).</summary>
  public const string FfmpegVariable = "GRCIS_FFMPEG";

  public VideoEncoder(string ffmpeg) => Ffmpeg = ffmpeg;

  public string Ffmpeg { get; }

  /// <summary>ffmpeg from <see cref="FfmpegVariable"/> or PATH, or null when there is none.</summary>
  public static VideoEncoder? Find()
  {
    string? configured = Environment.GetEnvironmentVariable(FfmpegVariable);
    string? path = string.IsNullOrWhiteSpace(configured) ? FindOnPath("ffmpeg") : Resolve(configured.Trim());
    return path == null ? null : new VideoEncoder(path);
  }

  /// <summary>One line for a user whose machine lacks ffmpeg.</summary>
  public static string MissingMessage()
  {
    string? configured = Environment.GetEnvironmentVariable(FfmpegVariable);
    return string.IsNullOrWhiteSpace(configured)
      ? $"--video needs ffmpeg, which is not installed (Debian/Ubuntu: apt-get install ffmpeg; or set {FfmpegVariable})"
      : $"--video needs ffmpeg, but {FfmpegVariable}='{configured}' is not an executable file";
  }

  /// <summary>Encodes frames <paramref name="first"/> … <paramref name="first"/> + <paramref name="count"/> − 1 of <paramref name="pattern"/>.</summary>
  /// <exception cref="CliFailure">ffmpeg failed; its last error line is in the message, no video file is left.</exception>
  public void Encode(FramePattern pattern, int first, int count, double fps, string output)
  {
    string full = Path.GetFullPath(output);
    string dir = Path.GetDirectoryName(full) ?? ".";
    string temp = Path.Combine(dir, "." + Path.GetFileNameWithoutExtension(full) + ".tmp-" + Guid.NewGuid().ToString("N")[..12] + Path.GetExtension(full));
    try
    {
      (int code, string error) = RunFfmpeg(pattern, first, count, fps, temp, "libx264");
      if (code != 0)
      {
        TryDelete(temp);
        (code, error) = RunFfmpeg(pattern, first, count, fps, temp, "mpeg4");
      }
      if (code != 0)
        throw new CliFailure($"ffmpeg could not encode '{full}' (exit {code}): {LastLine(error)}");
      File.Move(temp, full, overwrite: true);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException or System.ComponentModel.Win32Exception)
    {
      throw new CliFailure($"cannot write video '{full}': {e.Message}", e);
    }
    finally
    {
      TryDelete(temp);
    }
  }

  (int Code, string Error) RunFfmpeg(FramePattern pattern, int first, int count, double fps, string output, string codec)
  {
    var psi = new ProcessStartInfo(Ffmpeg)
    {
      RedirectStandardError = true,
      RedirectStandardOutput = true,
      RedirectStandardInput = true,
      UseShellExecute = false,
    };
    string rate = fps.ToString("R", CultureInfo.InvariantCulture);
    foreach (string a in new[]
    {
      "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
      "-framerate", rate, "-start_number", first.ToString(CultureInfo.InvariantCulture),
      "-i", pattern.FfmpegPattern(), "-frames:v", count.ToString(CultureInfo.InvariantCulture),
      "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-r", rate,
    })
      psi.ArgumentList.Add(a);
    if (codec == "libx264")
      foreach (string a in new[] { "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18" })
        psi.ArgumentList.Add(a);
    else
      foreach (string a in new[] { "-c:v", "mpeg4", "-pix_fmt", "yuv420p", "-q:v", "2" })
        psi.ArgumentList.Add(a);
    psi.ArgumentList.Add(output);

    using Process p = Process.Start(psi) ?? throw new CliFailure($"could not start ffmpeg ('{Ffmpeg}')");
    p.StandardInput.Close();
    var stdout = p.StandardOutput.ReadToEndAsync();
    string stderr = p.StandardError.ReadToEnd();
    p.WaitForExit();
    _ = stdout.Result;
    return (p.ExitCode, stderr);
  }

  static string LastLine(string text)
  {
    string[] lines = text.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
    return lines.Length == 0 ? "no message" : lines[^1];
  }

  static string? Resolve(string configured) =>
    configured.Contains(Path.DirectorySeparatorChar) || configured.Contains(Path.AltDirectorySeparatorChar)
      ? (IsExecutable(configured) ? Path.GetFullPath(configured) : null)
      : FindOnPath(configured);

  static string? FindOnPath(string name)
  {
    string? path = Environment.GetEnvironmentVariable("PATH");
    if (string.IsNullOrEmpty(path))
      return null;
    foreach (string dir in path.Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
    {
      foreach (string candidate in OperatingSystem.IsWindows() ? new[] { name + ".exe", name } : new[] { name })
      {
        string full = Path.Combine(dir, candidate);
        if (IsExecutable(full))
          return full;
      }
    }
    return null;
  }

  static bool IsExecutable(string path)
  {
    if (!File.Exists(path))
      return false;
    if (OperatingSystem.IsWindows())
      return true;
    UnixFileMode mode = File.GetUnixFileMode(path);
    return (mode & (UnixFileMode.UserExecute | UnixFileMode.GroupExecute | UnixFileMode.OtherExecute)) != 0;
  }

  static void TryDelete(string path)
  {
    try
    {
      if (File.Exists(path))
        File.Delete(path);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      // Best effort.
    }
  }
}
