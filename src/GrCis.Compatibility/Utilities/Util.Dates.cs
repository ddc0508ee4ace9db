using System;
using System.Globalization;

namespace Utilities;

/// <summary>GrCis's date and time helpers: days as text, durations, POSIX time stamps.</summary>
public static partial class Util
{
  /// <summary>One day in seconds.</summary>
  public const long DAY = 24 * 3600L;

  /// <summary>Earliest POSIX time (seconds from 1970) <see cref="UnixTimeStampToDateTime"/> accepts, about 100 years back.</summary>
  public const long MIN_UNIX_TIME = -100L * 365L * DAY;

  /// <summary>Latest POSIX time <see cref="UnixTimeStampToDateTime"/> accepts, about 130 years on.</summary>
  public const long MAX_UNIX_TIME = 130L * 365L * DAY;

  /// <summary>Dates before this one count as "no date".</summary>
  public static readonly DateTime DATE_EPSILON = DateTime.MinValue.AddDays(1);

  /// <summary>Formats <see cref="StringToDay(string)"/> tries (invariant culture) when the current culture's parser fails.</summary>
  public static readonly string[] DATE_FORMATS =
  {
    "yyyy/M/d", "M/d/yyyy", "MM/dd/yyyy", "yyyy-M-d", "yyyy-d-M", "d-M-yyyy",
    "yyyy", "d.M.yyyy", "d.M. yyyy", "d. M.yyyy", "d. M. yyyy", "d.M yyyy",
  };

  static readonly DateTime epoch = new(1970, 1, 1, 0, 0, 0, DateTimeKind.Utc);

  /// <summary>The day as "yyyy-MM-dd", or <paramref name="invalid"/> for "no date".</summary>
  public static string DayToString(DateTime dt, string invalid = "") =>
    dt < DATE_EPSILON ? invalid : dt.ToString("yyyy-MM-dd", CultureInfo.InvariantCulture);

  /// <summary>The date in <paramref name="s"/> (UTC); <see cref="DateTime.MinValue"/> for empty or unreadable text.</summary>
  public static DateTime StringToDay(string? s) =>
    StringToDay(s, out DateTime dt) && dt >= DATE_EPSILON ? dt : DateTime.MinValue;

  /// <summary>Reads a date as the current culture writes it or in one of <see cref="DATE_FORMATS"/>, taken as UTC.</summary>
  public static bool StringToDay(string? s, out DateTime dt)
  {
    const DateTimeStyles utc = DateTimeStyles.AssumeUniversal | DateTimeStyles.AdjustToUniversal;
    if (!string.IsNullOrEmpty(s) &&
        (DateTime.TryParse(s, CultureInfo.CurrentCulture, utc, out dt) ||
         DateTime.TryParseExact(s, DATE_FORMATS, CultureInfo.InvariantCulture, utc, out dt)))
      return true;
    dt = DateTime.MinValue;
    return false;
  }

  /// <summary>A duration in seconds as "m:ss", "h:mm:ss" or "d:hh:mm:ss".</summary>
  public static string FormatTime(long time)
  {
    long seconds = time % 60L, minutes = time / 60L % 60L, hours = time / 3600L % 24L, days = time / DAY;
    CultureInfo inv = CultureInfo.InvariantCulture;
    return days != 0L ? string.Create(inv, $"{days}:{hours:d2}:{minutes:d2}:{seconds:d2}")
      : hours != 0L ? string.Create(inv, $"{hours}:{minutes:d2}:{seconds:d2}")
      : string.Create(inv, $"{minutes}:{seconds:d2}");
  }

  /// <summary>Local time of a POSIX time stamp, clamped to [<see cref="MIN_UNIX_TIME"/>, <see cref="MAX_UNIX_TIME"/>].</summary>
  public static DateTime UnixTimeStampToDateTime(long unixTimeStamp) =>
    epoch.AddSeconds(Math.Clamp(unixTimeStamp, MIN_UNIX_TIME, MAX_UNIX_TIME)).ToLocalTime();

  /// <summary>Whole seconds from 1970-01-01 UTC to <paramref name="dt"/>.</summary>
  public static long DateTimeToUnixTimeStamp(DateTime dt) => (long)(dt.ToUniversalTime() - epoch).TotalSeconds;

  /// <summary>Now as a POSIX time stamp.</summary>
  public static long UnixTimeNow() => (long)(DateTime.UtcNow - epoch).TotalSeconds;

  /// <summary>The current UTC time in the given format (invariant culture).</summary>
  public static string FormatNowUtc(string fmt = "yyyy-MM-dd HH:mm:ss") =>
    DateTime.UtcNow.ToString(fmt, CultureInfo.InvariantCulture);

  /// <summary>POSIX time stamp of now plus <paramref name="rel"/> seconds.</summary>
  public static long RelativeTime(long rel) => DateTimeToUnixTimeStamp(DateTime.Now.AddSeconds(rel));

  /// <summary>
  /// Reads a duration: an integer with an optional unit w(eeks), d(ays), h(ours), m(inutes) or s(econds, the default),
  /// into seconds. Leaves <paramref name="time"/> unchanged and returns false for anything else.
  /// </summary>
  public static bool ParseRelativeTime(string? value, ref long time)
  {
    if (string.IsNullOrEmpty(value))
      return false;
    long unit = 1L;
    if (char.IsLetter(value[^1]))
    {
      unit = char.ToLowerInvariant(value[^1]) switch
      {
        'w' => 7L * DAY,
        'd' => DAY,
        'h' => 3600L,
        'm' => 60L,
        _ => 1L,
      };
      value = value[..^1];
    }
    if (!long.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, out long count))
      return false;
    time = count * unit;
    return true;
  }
}
