using System;
using System.Globalization;

namespace GrCis.Cli.Jobs;

/// <summary>
/// The most memory grcis's managed heap may use (<c>--memory-limit</c>). Without one, a script that keeps allocating
/// grows until the kernel kills the process (exit 137, nothing printed); with one, the allocation over it throws
/// <see cref="OutOfMemoryException"/> in the script, which is reported with the script's line. .NET reads its heap hard
/// limit at start-up, but takes a new one at run time through <c>AppContext.SetData("GCHeapHardLimit")</c> and
/// <see cref="GC.RefreshMemoryLimit"/>, so no second process is needed.
/// </summary>
public static class MemoryLimit
{
  /// <summary>The default share of the memory the machine (or its container) gives the process.</summary>
  public const double DefaultShare = 0.75;

  /// <summary>The limit this process set (bytes), or 0 when it set none.</summary>
  public static long Applied { get; private set; }

  /// <summary>
  /// Bytes of <paramref name="text"/>: a size with an optional binary unit (<c>4G</c>, <c>512M</c>, <c>1.5GiB</c>,
  /// <c>300000000</c>), a share of the memory the process is given (<c>50%</c>), or 0 for <c>0</c>, <c>none</c> (no limit).
  /// </summary>
  /// <exception cref="UsageException">The text is none of these.</exception>
  public static long Parse(string text, long totalAvailable)
  {
    string t = text.Trim();
    if (t is "0" || t.Equals("none", StringComparison.OrdinalIgnoreCase))
      return 0;
    if (t.EndsWith('%'))
    {
      if (double.TryParse(t[..^1], NumberStyles.Float, CultureInfo.InvariantCulture, out double percent) && percent > 0 && percent <= 100)
        return (long)(totalAvailable * (percent / 100));
      throw Invalid(text, "a percentage is more than 0 and at most 100");
    }
    string number = t;
    long unit = 1;
    string upper = t.ToUpperInvariant();
    foreach ((string suffix, long factor) in Units)
      if (upper.EndsWith(suffix, StringComparison.Ordinal))
      {
        number = t[..^suffix.Length].TrimEnd();
        unit = factor;
        break;
      }
    if (!double.TryParse(number, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !(value > 0) ||
        value * unit >= long.MaxValue)
      throw Invalid(text, null);
    return (long)(value * unit);
  }

  // Longest first, so "GIB" is not read as "B".
  static readonly (string Suffix, long Factor)[] Units =
  [
    ("KIB", 1L << 10), ("MIB", 1L << 20), ("GIB", 1L << 30), ("TIB", 1L << 40),
    ("KB", 1L << 10), ("MB", 1L << 20), ("GB", 1L << 30), ("TB", 1L << 40),
    ("K", 1L << 10), ("M", 1L << 20), ("G", 1L << 30), ("T", 1L << 40), ("B", 1),
  ];

  static UsageException Invalid(string text, string? why) =>
    new($"invalid --memory-limit '{text}': {(why != null ? why + "; " : "")}give a size (e.g. 4G, 512M), a share of the memory (e.g. 50%), or 0 or none for no limit");

  /// <summary>The memory the runtime sees for this process (the machine's, a container's, or a limit already set).</summary>
  public static long TotalAvailable => GC.GetGCMemoryInfo().TotalAvailableMemoryBytes;

  /// <summary>True when the environment already set a heap limit (<c>DOTNET_GCHeapHardLimit</c> or the runtime configuration).</summary>
  public static bool SetByEnvironment()
  {
    foreach (string prefix in new[] { "DOTNET_", "COMPlus_" })
      foreach (string name in new[] { "GCHeapHardLimit", "GCHeapHardLimitPercent" })
        if (!string.IsNullOrEmpty(Environment.GetEnvironmentVariable(prefix + name)))
          return true;
    return AppContext.GetData("GCHeapHardLimit") != null || AppContext.GetData("System.GC.HeapHardLimit") != null ||
           AppContext.GetData("GCHeapHardLimitPercent") != null || AppContext.GetData("System.GC.HeapHardLimitPercent") != null;
  }

  /// <summary>The smallest limit taken: grcis itself (the compiler on a cache miss) needs about this much.</summary>
  public const long Minimum = 64L << 20;

  /// <summary>
  /// The limit to set (bytes; 0 = none): <paramref name="text"/> as <see cref="Parse"/> reads it, or when null,
  /// <see cref="DefaultShare"/> of <paramref name="totalAvailable"/>, unless <paramref name="setByEnvironment"/>.
  /// </summary>
  /// <exception cref="UsageException">The text is malformed or below <see cref="Minimum"/>.</exception>
  public static long Resolve(string? text, long totalAvailable, bool setByEnvironment)
  {
    if (text == null)
      return setByEnvironment ? 0 : (long)(totalAvailable * DefaultShare);
    long bytes = Parse(text, totalAvailable);
    if (bytes != 0 && bytes < Minimum)
      throw Invalid(text, $"{Describe(bytes)} is less than grcis needs itself ({Describe(Minimum)})");
    return bytes;
  }

  /// <summary>Sets the heap hard limit of this process to what <see cref="Resolve"/> makes of <paramref name="text"/>.</summary>
  /// <exception cref="UsageException">The text is malformed, or the limit is below what the process already uses.</exception>
  public static void Apply(string? text)
  {
    long bytes = Resolve(text, TotalAvailable, SetByEnvironment());
    if (bytes == 0)
      return;
    AppContext.SetData("GCHeapHardLimit", (ulong)bytes);
    try
    {
      GC.RefreshMemoryLimit();
    }
    catch (InvalidOperationException)
    {
      AppContext.SetData("GCHeapHardLimit", null);
      GC.RefreshMemoryLimit();
      throw Invalid(text ?? Describe(bytes), $"{Describe(bytes)} is less than grcis already uses");
    }
    Applied = bytes;
  }

  /// <summary>Bytes as a short text (MiB or GiB).</summary>
  public static string Describe(long bytes) => bytes >= 10L << 30
    ? (bytes / (double)(1L << 30)).ToString("0.#", CultureInfo.InvariantCulture) + " GiB"
    : (bytes / (double)(1L << 20)).ToString("0", CultureInfo.InvariantCulture) + " MiB";

  /// <summary>What an out-of-memory error adds: the limit in force, and how to change it.</summary>
  public static string Hint() => Applied > 0
    ? $" (grcis may use {Describe(Applied)}; --memory-limit sets it)"
    : "";
}
