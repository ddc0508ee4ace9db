using System;
using System.Collections.Concurrent;
using System.IO;

namespace Rendering.Imaging;

/// <summary>
/// Writes a file via a temporary sibling and a rename, so readers (and a crash) never see a half-written
/// image and a failed save leaves any existing file untouched.
/// </summary>
internal static class AtomicFile
{
  // Temporary files being written: removed if the process exits mid-save (Ctrl+C's forced exit).
  static readonly ConcurrentDictionary<string, byte> pending = new();

  static AtomicFile() => AppDomain.CurrentDomain.ProcessExit += (_, _) =>
  {
    foreach (string temp in pending.Keys)
      TryDelete(temp);
  };

  public static void Write(string path, Action<Stream> write)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    ArgumentNullException.ThrowIfNull(write);

    // Same directory as the target so File.Move is a rename on one file system.
    string temp = path + ".tmp-" + Guid.NewGuid().ToString("N")[..12];
    pending.TryAdd(temp, 0);
    try
    {
      using (FileStream fs = new(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
      {
        write(fs);
        fs.Flush(flushToDisk: true);
      }
      File.Move(temp, path, overwrite: true);
    }
    catch (Exception ex)
    {
      TryDelete(temp);
      if (ex is IOException or UnauthorizedAccessException or NotSupportedException)
        throw new ImageSaveException(path, ex);
      throw;
    }
    finally
    {
      pending.TryRemove(temp, out _);
    }
  }

  private static void TryDelete(string temp)
  {
    try
    {
      File.Delete(temp);
    }
    catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
    {
      // The original failure matters more than a leftover temp file.
    }
  }
}
