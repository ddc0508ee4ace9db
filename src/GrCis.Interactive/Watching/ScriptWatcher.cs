using System;
using System.IO;
using System.Security.Cryptography;
using System.Threading;

namespace GrCis.Interactive;

/// <summary>
/// Watches a script file and reports when its content changed (the student saves in an editor, the
/// demo re-renders). A <see cref="FileSystemWatcher"/> gives quick notice; polling catches what it
/// misses (network drives, some editors' rename dance, containers). Notices are debounced and only a
/// real content change (hash) is reported, once.
/// </summary>
public sealed class ScriptWatcher : IDisposable
{
  readonly object sync = new();
  readonly FileSystemWatcher? fsw;
  readonly Timer poll;
  readonly Timer debounce;
  (DateTime, long) stamp;
  byte[]? lastHash;
  bool disposed;

  public ScriptWatcher(string path, TimeSpan? debounce = null, TimeSpan? pollInterval = null, bool useFileSystemWatcher = true)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    Path = System.IO.Path.GetFullPath(path);
    Debounce = debounce ?? TimeSpan.FromMilliseconds(300);
    PollInterval = pollInterval ?? TimeSpan.FromSeconds(1);
    stamp = Stamp();
    lastHash = HashOrNull();

    this.debounce = new Timer(_ => Fire(), null, Timeout.Infinite, Timeout.Infinite);
    poll = new Timer(_ => Poll(), null, PollInterval, PollInterval);
    if (useFileSystemWatcher)
    {
      try
      {
        fsw = new FileSystemWatcher(System.IO.Path.GetDirectoryName(Path)!, System.IO.Path.GetFileName(Path))
        {
          NotifyFilter = NotifyFilters.LastWrite | NotifyFilters.Size | NotifyFilters.FileName | NotifyFilters.CreationTime,
        };
        fsw.Changed += (_, _) => Poke();
        fsw.Created += (_, _) => Poke();
        fsw.Renamed += (_, _) => Poke();
        fsw.EnableRaisingEvents = true;
      }
      catch (Exception ex) when (ex is IOException or ArgumentException or PlatformNotSupportedException)
      {
        // No watcher here (e.g. inotify limit reached): polling alone still works.
        fsw?.Dispose();
        fsw = null;
      }
    }
  }

  public string Path { get; }

  public TimeSpan Debounce { get; }

  public TimeSpan PollInterval { get; }

  /// <summary>True when the file-system watcher is active (otherwise only polling).</summary>
  public bool UsesFileSystemWatcher => fsw != null;

  /// <summary>The file's content changed. Raised on a thread-pool thread.</summary>
  public event EventHandler<ScriptChangedEventArgs>? Changed;

  void Poll()
  {
    (DateTime, long) now = Stamp();
    bool changed;
    lock (sync)
    {
      changed = now != stamp;
      stamp = now;
    }
    if (changed)
      Poke();
  }

  void Poke()
  {
    lock (sync)
      if (!disposed)
        debounce.Change(Debounce, Timeout.InfiniteTimeSpan);
  }

  void Fire()
  {
    byte[]? hash = HashOrNull();
    lock (sync)
    {
      if (disposed || hash == null)
        return; // missing or locked mid-save: the next notice or poll retries
      if (lastHash != null && hash.AsSpan().SequenceEqual(lastHash))
        return;
      lastHash = hash;
    }
    Changed?.Invoke(this, new ScriptChangedEventArgs(Path));
  }

  (DateTime, long) Stamp()
  {
    try
    {
      var fi = new FileInfo(Path);
      return fi.Exists ? (fi.LastWriteTimeUtc, fi.Length) : (DateTime.MinValue, -1L);
    }
    catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
    {
      return (DateTime.MinValue, -1L);
    }
  }

  byte[]? HashOrNull()
  {
    try
    {
      return SHA256.HashData(File.ReadAllBytes(Path));
    }
    catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
    {
      return null;
    }
  }

  public void Dispose()
  {
    lock (sync)
    {
      if (disposed)
        return;
      disposed = true;
    }
    fsw?.Dispose();
    poll.Dispose();
    debounce.Dispose();
  }
}
