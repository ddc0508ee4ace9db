using System;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's date helpers: days as text, durations, POSIX time.</summary>
public class UtilDatesTests
{
  [Theory]
  [InlineData(59L, "0:59")]
  [InlineData(61L, "1:01")]
  [InlineData(3600L + 5 * 60 + 7, "1:05:07")]
  [InlineData(2 * Util.DAY + 3 * 3600 + 4 * 60 + 5, "2:03:04:05")]
  public void FormatTime_shows_only_the_units_needed(long seconds, string expected) =>
    Assert.Equal(expected, Util.FormatTime(seconds));

  [Theory]
  [InlineData("90", 90L)]
  [InlineData("5m", 300L)]
  [InlineData("2H", 7200L)]
  [InlineData("3d", 3 * Util.DAY)]
  [InlineData("1w", 7 * Util.DAY)]
  [InlineData("-1h", -3600L)]
  public void ParseRelativeTime_reads_units(string text, long expected)
  {
    long t = 0;
    Assert.True(Util.ParseRelativeTime(text, ref t));
    Assert.Equal(expected, t);
  }

  [Theory]
  [InlineData("")]
  [InlineData("h")]
  [InlineData("1.5h")]
  public void ParseRelativeTime_of_bad_text_keeps_the_value(string text)
  {
    long t = 17;
    Assert.False(Util.ParseRelativeTime(text, ref t));
    Assert.Equal(17, t);
  }

  [Theory]
  [InlineData("2024-03-13")]
  [InlineData("2024/3/13")]
  [InlineData("13.3.2024")]     // not a date for the invariant culture: read by the d.M.yyyy fallback
  [InlineData("13. 3. 2024")]
  public void StringToDay_reads_the_accepted_formats_as_UTC(string text)
  {
    Assert.True(Util.StringToDay(text, out DateTime dt));
    Assert.Equal(new DateTime(2024, 3, 13), dt.Date);
    Assert.Equal(DateTimeKind.Utc, dt.Kind);
    Assert.Equal("2024-03-13", Util.DayToString(Util.StringToDay(text)));
  }

  [Fact]
  public void No_date_is_MinValue_and_prints_as_the_invalid_text()
  {
    Assert.False(Util.StringToDay("not a date", out DateTime dt));
    Assert.Equal(DateTime.MinValue, dt);
    Assert.Equal(DateTime.MinValue, Util.StringToDay(""));
    Assert.Equal("n/a", Util.DayToString(DateTime.MinValue, "n/a"));
    Assert.Equal("", Util.DayToString(Util.DATE_EPSILON.AddHours(-1)));
  }

  [Fact]
  public void Unix_time_stamps_round_trip_and_clamp()
  {
    var moment = new DateTime(2001, 9, 9, 1, 46, 40, DateTimeKind.Utc);
    Assert.Equal(1_000_000_000L, Util.DateTimeToUnixTimeStamp(moment));
    Assert.Equal(moment, Util.UnixTimeStampToDateTime(1_000_000_000L).ToUniversalTime());
    Assert.Equal(Util.MAX_UNIX_TIME, Util.DateTimeToUnixTimeStamp(Util.UnixTimeStampToDateTime(long.MaxValue)));
    Assert.Equal(Util.MIN_UNIX_TIME, Util.DateTimeToUnixTimeStamp(Util.UnixTimeStampToDateTime(long.MinValue)));
  }

  [Fact]
  public void Now_helpers_agree_with_the_clock()
  {
    long before = Util.DateTimeToUnixTimeStamp(DateTime.UtcNow);
    long now = Util.UnixTimeNow();
    long later = Util.RelativeTime(Util.DAY);
    Assert.InRange(now - before, 0, 2);
    Assert.InRange(later - now - Util.DAY, 0, 2);
    Assert.True(DateTime.TryParse(Util.FormatNowUtc("yyyy-MM-ddTHH:mm:ssZ"), out _));
    Assert.Equal(4, Util.FormatNowUtc("yyyy").Length);
  }
}
