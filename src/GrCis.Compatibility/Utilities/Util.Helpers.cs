using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace Utilities;

/// <summary>GrCis's general helpers that students' code calls: clamping, percentages, yes/no text, the log file.</summary>
public static partial class Util
{
  /// <summary>The file <see cref="Log"/> appends to (relative to the current directory, as in GrCis).</summary>
  public static string logFileName = "log.txt";

  static readonly object logLock = new();
  static bool firstLog = true;

  /// <summary><paramref name="val"/> limited to [<paramref name="min"/>, <paramref name="max"/>].</summary>
  public static T Clamp<T>(T val, T min, T max) where T : IComparable<T> => MathSupport.Arith.Clamp(val, min, max);

  /// <summary>Clamps to [0, 1].</summary>
  public static float Saturate(float val) => val < 0.0f ? 0.0f : val > 1.0f ? 1.0f : val;

  /// <summary>Clamps to [0, 1].</summary>
  public static double Saturate(double val) => val < 0.0 ? 0.0 : val > 1.0 ? 1.0 : val;

  /// <summary>Number of bits set in <paramref name="i"/>.</summary>
  public static int bits(int i) => System.Numerics.BitOperations.PopCount((uint)i);

  /// <summary><c>default(T)</c>.</summary>
  public static T? DefaultValue<T>() => default;

  /// <summary>True only for "1", "yes", "true" or "ano" (Czech "yes"), in any case.</summary>
  public static bool positiveStrict(string? val) =>
    val != null && (val == "1" || val.Equals("yes", StringComparison.OrdinalIgnoreCase) ||
                    val.Equals("true", StringComparison.OrdinalIgnoreCase) || val.Equals("ano", StringComparison.OrdinalIgnoreCase));

  public static string YesNo(bool b) => b ? "yes" : "no";

  /// <summary><paramref name="count"/> as a percentage of <paramref name="total"/>; a total below 1 counts as 1.</summary>
  public static double percent(double count, double total) => 100.0 * count / Math.Max(total, 1.0);

  public static double percent(long count, long total) => 100.0 * count / Math.Max(total, 1L);

  public static double percent(int count, int total) => 100.0 * count / Math.Max(total, 1);

  /// <summary>Null for an empty string, the string otherwise.</summary>
  public static string? EmptyNull(string? s) => string.IsNullOrEmpty(s) ? null : s;

  /// <summary>Appends a time-stamped line to <see cref="logFileName"/> and returns the message.</summary>
  public static string Log(string msg)
  {
    try
    {
      lock (logLock)
      {
        using var log = new StreamWriter(logFileName, append: true);
        if (firstLog)
          log.WriteLine();
        log.WriteLine($"{DateTime.Now.ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture)}: {msg}");
        firstLog = false;
      }
    }
    catch (IOException e)
    {
      // A log that cannot be written must not stop the render.
      Console.Error.WriteLine($"Util.Log: cannot write '{logFileName}': {e.Message}");
    }
    return msg;
  }

  /// <summary><see cref="Log"/> of an invariant-culture format.</summary>
  public static string LogFormat(string fmt, params object[] pars) =>
    Log(string.Format(CultureInfo.InvariantCulture, fmt, pars));

  public static void LogArray(string prefix, float[] rcoord, string format = "f4")
  {
    var sb = new StringBuilder(prefix);
    foreach (float v in rcoord)
      sb.Append(' ').Append(v.ToString(format, CultureInfo.InvariantCulture));
    Log(sb.ToString());
  }

  public static void LogArray(string prefix, string[] names) =>
    Log($"{prefix} \"{string.Join("\" \"", names)}\"");

  public static void LogArray(string prefix, bool[] flags)
  {
    var sb = new StringBuilder(prefix);
    foreach (bool f in flags)
      sb.Append(" \"").Append(f).Append('"');
    Log(sb.ToString());
  }
}
