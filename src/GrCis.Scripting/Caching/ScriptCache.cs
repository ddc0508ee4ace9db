using System;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Threading;
using GrCis.Scripting.Compilation;

namespace GrCis.Scripting.Caching;

/// <summary>
/// Compiled scene scripts and modules kept on disk between runs, so a script is compiled once per change rather
/// than once per process. An entry is keyed by everything its compilation depends on (see <see cref="CacheKeys"/>)
/// and holds what a run needs afterwards: the assembly and its PDB, the warnings, and the maps back to the user's
/// lines. Safe for several processes at once (the shards of an animation): an entry is written to a temporary
/// file and renamed into place, so a reader sees a whole entry or none, and an entry that is missing, cut short
/// or corrupt is only a miss (the script is compiled and the entry replaced). No lock is held while compiling.
/// The folder is bounded: beyond <see cref="MaxBytes"/> or <see cref="MaxEntries"/> the entries used least
/// recently are deleted. Pass one to <see cref="ScriptHost"/>; counters tell hits from compilations.
/// <para>
/// What the folder holds is code this program runs, so it is trusted only as far as nobody else can write it: on Unix
/// the folder must belong to the user and not be writable by group or others (else it is not used, with one warning),
/// an entry is read only when it is a regular file of the user's (a link, a FIFO or a device is a miss), and every
/// entry carries an HMAC under a random secret of the user's kept in the folder, readable by the user alone
/// (<see cref="KeyFileName"/>), so an entry nobody holding the secret wrote is never loaded.
/// </para>
/// </summary>
public sealed class ScriptCache
{
  /// <summary>Environment variable naming the cache folder (instead of the platform's cache folder).</summary>
  public const string DirectoryVariable = "GRCIS_CACHE_DIR";

  /// <summary>Environment variable that turns the cache off (<c>1</c>, <c>true</c> or <c>yes</c>).</summary>
  public const string DisableVariable = "GRCIS_NO_CACHE";

  /// <summary>Default bound of the folder's size: 200 MiB.</summary>
  public const long DefaultMaxBytes = 200L * 1024 * 1024;

  /// <summary>Default bound of the number of entries.</summary>
  public const int DefaultMaxEntries = 2000;

  /// <summary>File name ending of an entry.</summary>
  public const string EntryExtension = ".grcis-compiled";

  const string TemporaryExtension = ".tmp";

  /// <summary>The file in the folder holding the secret entries are signed with (32 random bytes, the user's alone).</summary>
  public const string KeyFileName = ".grcis-cache-key";

  const int KeyLength = 32;

  // Folders already warned about in this process: one warning each.
  static readonly System.Collections.Concurrent.ConcurrentDictionary<string, bool> warned = new(StringComparer.Ordinal);

  readonly TextWriter? warnings;
  readonly object openLock = new();
  bool opened;
  byte[]? secret;

  // A temporary file this old belongs to a writer that died; it is removed when the folder is trimmed.
  static readonly TimeSpan staleTemporary = TimeSpan.FromHours(1);

  int hits, misses, rejected, stores;

  /// <param name="directory">The folder of the entries (created when the first one is written).</param>
  /// <param name="maxBytes">Bound of the entries' total size.</param>
  /// <param name="maxEntries">Bound of their number.</param>
  /// <param name="warnings">Where the one line saying why the folder is not used goes (default: standard error).</param>
  public ScriptCache(string directory, long maxBytes = DefaultMaxBytes, int maxEntries = DefaultMaxEntries, TextWriter? warnings = null)
  {
    this.warnings = warnings;
    ArgumentException.ThrowIfNullOrEmpty(directory);
    ArgumentOutOfRangeException.ThrowIfNegativeOrZero(maxBytes);
    ArgumentOutOfRangeException.ThrowIfNegativeOrZero(maxEntries);
    Directory = Path.GetFullPath(directory);
    MaxBytes = maxBytes;
    MaxEntries = maxEntries;
  }

  /// <summary>The folder of the entries.</summary>
  public string Directory { get; }

  public long MaxBytes { get; }

  public int MaxEntries { get; }

  /// <summary>Scripts and modules loaded from an entry instead of compiled.</summary>
  public int Hits => Volatile.Read(ref hits);

  /// <summary>Look-ups that found no usable entry (the script or module was compiled).</summary>
  public int Misses => Volatile.Read(ref misses);

  /// <summary>Entries found unusable (cut short, corrupt, another key's or format's) and replaced.</summary>
  public int Rejected => Volatile.Read(ref rejected);

  /// <summary>Entries written.</summary>
  public int Stores => Volatile.Read(ref stores);

  /// <summary>
  /// Why the folder <paramref name="directory"/> of (or in) a cache may not be trusted with what steers grcis (another
  /// user owns it, or others may write it), or null when it is the user's alone; nothing is checked on Windows.
  /// </summary>
  public static string? WhyUntrusted(string directory) => CacheFolderTrust.Untrusted(directory);

  /// <summary>
  /// The cache the environment asks for: null when <see cref="DisableVariable"/> is set, else one in
  /// <see cref="DefaultDirectory"/> (null too when no folder can be named: no home folder).
  /// </summary>
  public static ScriptCache? FromEnvironment()
  {
    if (Environment.GetEnvironmentVariable(DisableVariable) is string off &&
        (off == "1" || off.Equals("true", StringComparison.OrdinalIgnoreCase) || off.Equals("yes", StringComparison.OrdinalIgnoreCase)))
      return null;
    string? dir = DefaultDirectory();
    return dir == null ? null : new ScriptCache(dir);
  }

  /// <summary>
  /// <see cref="DirectoryVariable"/> when set; else <c>grcis/scripts</c> in the platform's cache folder:
  /// <c>$XDG_CACHE_HOME</c> or <c>~/.cache</c> on Linux and other Unix systems, <c>~/Library/Caches</c> on macOS,
  /// the local application data folder on Windows (<c>%LOCALAPPDATA%\grcis\cache\scripts</c>). Null when none is known.
  /// </summary>
  public static string? DefaultDirectory() => DefaultDirectory(Environment.GetEnvironmentVariable);

  /// <summary><see cref="DefaultDirectory()"/> with the environment read through <paramref name="variable"/>.</summary>
  internal static string? DefaultDirectory(Func<string, string?> variable)
  {
    if (variable(DirectoryVariable) is { Length: > 0 } given)
      return Path.GetFullPath(given);
    if (OperatingSystem.IsWindows())
    {
      string local = Environment.GetFolderPath(Environment.SpecialFolder.LocalApplicationData);
      return local.Length == 0 ? null : Path.Combine(local, "grcis", "cache", "scripts");
    }
    string home = Environment.GetFolderPath(Environment.SpecialFolder.UserProfile);
    if (OperatingSystem.IsMacOS())
      return home.Length == 0 ? null : Path.Combine(home, "Library", "Caches", "grcis", "scripts");
    // The XDG base directory rules: a relative XDG_CACHE_HOME is to be ignored.
    if (variable("XDG_CACHE_HOME") is { Length: > 0 } xdg && Path.IsPathFullyQualified(xdg))
      return Path.Combine(xdg, "grcis", "scripts");
    return home.Length == 0 ? null : Path.Combine(home, ".cache", "grcis", "scripts");
  }

  /// <summary>Deletes every entry (an entry another process is writing at the same time may stay).</summary>
  public void Clear()
  {
    if (!System.IO.Directory.Exists(Directory))
      return;
    foreach (string file in System.IO.Directory.EnumerateFiles(Directory, "*" + EntryExtension))
      TryDelete(file);
  }

  /// <summary>Why the folder is not used (another user's, writable by others, its secret not private), or null while it is usable.</summary>
  public string? Refused { get; private set; }

  internal ScriptImage? ReadScript(string key) => Read(key, CacheEntries.ReadScript);

  internal ModuleImage? ReadModule(string key) => Read(key, CacheEntries.ReadModule);

  internal void Write(string key, ScriptImage image)
  {
    if (Secret() is byte[] s)
      Write(key, CacheEntries.Write(key, image, s));
  }

  internal void Write(string key, ModuleImage image)
  {
    if (Secret() is byte[] s)
      Write(key, CacheEntries.Write(key, image, s));
  }

  /// <summary>
  /// The secret entries are signed with, once the folder is found trustworthy (made, private to the user, when
  /// missing); null when the cache cannot be used: the folder cannot be made (only costs compilations, silently) or is
  /// not trusted (<see cref="Refused"/>, one warning).
  /// </summary>
  byte[]? Secret()
  {
    lock (openLock)
    {
      if (!opened)
      {
        opened = true;
        try
        {
          CreateFolder();
          Refused = CacheFolderTrust.Untrusted(Directory);
          if (Refused == null)
            (secret, Refused) = LoadOrCreateSecret();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
          secret = null;
        }
        if (Refused != null && warned.TryAdd(Directory, true))
          (warnings ?? Console.Error).WriteLine($"grcis: warning: the compiled-script cache '{Directory}' is not used: {Refused}; scripts are compiled afresh");
      }
      return Refused == null ? secret : null;
    }
  }

  (byte[]? Secret, string? Refused) LoadOrCreateSecret()
  {
    string path = Path.Combine(Directory, KeyFileName);
    if (!Exists(path))
    {
      // Written whole under another name, then moved into place without replacing: processes that start together agree on one.
      string temporary = Path.Combine(Directory, $"{KeyFileName}.{Environment.ProcessId}.{Guid.NewGuid():N}{TemporaryExtension}");
      var options = new FileStreamOptions { Mode = FileMode.CreateNew, Access = FileAccess.Write, Share = FileShare.None };
      if (!OperatingSystem.IsWindows())
        options.UnixCreateMode = UnixFileMode.UserRead | UnixFileMode.UserWrite;
      try
      {
        using (var stream = new FileStream(temporary, options))
          stream.Write(RandomNumberGenerator.GetBytes(KeyLength));
        File.Move(temporary, path, overwrite: false);
      }
      catch (IOException) when (Exists(path))
      {
        // Another process made it first: theirs is used.
      }
      finally
      {
        TryDelete(temporary);
      }
    }
    if (CacheFolderTrust.UntrustedSecret(path) is string why)
      return (null, why);
    byte[]? bytes = ReadRegularFile(path, KeyLength);
    return bytes is { Length: KeyLength } ? (bytes, null)
      : (null, $"its secret '{KeyFileName}' is not {KeyLength} bytes (delete it, and a new one is made)");
  }

  /// <summary>True when <paramref name="path"/> names anything, a dangling link included.</summary>
  static bool Exists(string path) =>
    File.Exists(path) || System.IO.Directory.Exists(path) || !OperatingSystem.IsWindows() && UnixFileStatus.OfLink(path) != null;

  /// <summary>
  /// The bytes of <paramref name="path"/> when it is a regular file of the user's of at most <paramref name="maxLength"/>
  /// bytes, else null: a link (to /dev/zero), a FIFO (whose open would wait for a writer) or a device is never opened.
  /// </summary>
  static byte[]? ReadRegularFile(string path, long maxLength)
  {
    if (!OperatingSystem.IsWindows())
    {
      if (UnixFileStatus.OfLink(path) is not { IsRegularFile: true } status || status.Uid != UnixFileStatus.CurrentUser || status.Size > maxLength)
        return null;
    }
    else if (new FileInfo(path) is { Exists: false } or { LinkTarget: not null } || new FileInfo(path).Length > maxLength)
      return null;
    using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read);
    if (stream.Length > maxLength)
      return null;
    byte[] bytes = new byte[stream.Length];
    stream.ReadExactly(bytes);
    return bytes;
  }

  /// <summary>An entry was read but its code could not be loaded: it is removed, and counted as rejected and missed, not hit.</summary>
  internal void Reject(string key)
  {
    Interlocked.Decrement(ref hits);
    Interlocked.Increment(ref misses);
    Interlocked.Increment(ref rejected);
    TryDelete(EntryPath(key));
  }

  string EntryPath(string key) => Path.Combine(Directory, key + EntryExtension);

  T? Read<T>(string key, Func<byte[], string, byte[], T?> parse) where T : class
  {
    string path = EntryPath(key);
    byte[]? bytes;
    byte[] signing;
    try
    {
      if (Secret() is not byte[] s || !Exists(path))
      {
        Interlocked.Increment(ref misses);
        return null;
      }
      bytes = ReadRegularFile(path, MaxBytes);
      if (bytes == null)
      {
        // Not a regular file of the user's (a link, a FIFO, a device), or too big: unusable, and replaced.
        Interlocked.Increment(ref rejected);
        Interlocked.Increment(ref misses);
        TryDelete(path);
        return null;
      }
      signing = s;
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      Interlocked.Increment(ref misses);
      return null;
    }
    T? entry = parse(bytes, key, signing);
    if (entry == null)
    {
      Interlocked.Increment(ref rejected);
      Interlocked.Increment(ref misses);
      TryDelete(path);
      return null;
    }
    Interlocked.Increment(ref hits);
    // Marks the entry as used: trimming deletes the least recently used ones first.
    try
    {
      File.SetLastWriteTimeUtc(path, DateTime.UtcNow);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
    }
    return entry;
  }

  void Write(string key, byte[] entry)
  {
    string temporary = Path.Combine(Directory, $"{key}.{Environment.ProcessId}.{Guid.NewGuid():N}{TemporaryExtension}");
    try
    {
      CreateFolder();
      using (var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write, FileShare.None))
        stream.Write(entry);
      // Atomic on one file system: another process reads the old entry, the new one, or none, never a part.
      File.Move(temporary, EntryPath(key), overwrite: true);
      Interlocked.Increment(ref stores);
      Trim();
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      // A cache that cannot be written (read-only home, full disk, an entry open elsewhere on Windows) only costs time.
      TryDelete(temporary);
    }
  }

  /// <summary>The folder, private to the user on Unix: what it holds is code this program runs.</summary>
  void CreateFolder()
  {
    if (OperatingSystem.IsWindows())
      System.IO.Directory.CreateDirectory(Directory);
    else
      System.IO.Directory.CreateDirectory(Directory, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
  }

  /// <summary>Deletes the least recently used entries beyond the bounds, and temporary files of writers that died.</summary>
  void Trim()
  {
    FileInfo[] files = new DirectoryInfo(Directory).GetFiles();
    DateTime stale = DateTime.UtcNow - staleTemporary;
    foreach (FileInfo f in files)
      if (f.Name.EndsWith(TemporaryExtension, StringComparison.Ordinal) && f.LastWriteTimeUtc < stale)
        TryDelete(f.FullName);

    FileInfo[] entries = files.Where(f => f.Name.EndsWith(EntryExtension, StringComparison.Ordinal)).ToArray();
    long total = entries.Sum(f => f.Length);
    if (entries.Length <= MaxEntries && total <= MaxBytes)
      return;
    int count = entries.Length;
    foreach (FileInfo f in entries.OrderBy(f => f.LastWriteTimeUtc))
    {
      if (count <= MaxEntries && total <= MaxBytes)
        break;
      TryDelete(f.FullName);
      count--;
      total -= f.Length;
    }
  }

  static void TryDelete(string path)
  {
    try
    {
      File.Delete(path);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
    }
  }
}
