using System;
using Rendering.Execution;
using Rendering.Imaging;
using Xunit;

namespace Rendering.Tests.Imaging;

public class DisplayEncodingTests
{
  [Fact]
  public void Render_encoding_truncates_where_linear_round_rounds()
  {
    // 0.5 * 255 = 127.5: the two rules differ exactly here.
    Assert.Equal(127, DisplayEncoding.ForRender(1.0).Encode(0.5f));
    Assert.Equal(128, DisplayEncoding.LinearRound.Encode(0.5f));
    Assert.Equal(Quantization.Truncate, DisplayEncoding.ForRender(2.2).Quantization);
  }

  [Theory]
  [InlineData(0.0)]
  [InlineData(0.001)]
  [InlineData(-3.0)]
  public void Render_gamma_at_or_below_a_thousandth_is_linear_as_GrCis_ApplyGamma(double gamma)
  {
    Assert.Equal(1.0, DisplayEncoding.ForRender(gamma).Gamma);
    Assert.Equal(63, DisplayEncoding.ForRender(gamma).Encode(0.25f));
  }

  [Fact]
  public void Gamma_is_applied_before_quantization()
  {
    // 0.25^(1/2) = 0.5 -> 127 truncated.
    Assert.Equal(127, DisplayEncoding.ForRender(2.0).Encode(0.25f));
    Assert.Equal(128, new DisplayEncoding(2.0, Quantization.Round).Encode(0.25f));
  }

  [Theory]
  [InlineData(float.NaN, 0)]
  [InlineData(-1f, 0)]
  [InlineData(1f, 255)]
  [InlineData(7f, 255)]
  [InlineData(float.PositiveInfinity, 255)]
  public void Out_of_range_values_clamp_and_NaN_is_black(float v, int expected) =>
    Assert.Equal(expected, DisplayEncoding.ForRender(2.2).Encode(v));

  [Fact]
  public void Span_variant_matches_value_by_value_and_checks_length()
  {
    float[] values = [0f, 0.1f, 0.33f, 0.5f, 0.9f, 1.2f];
    byte[] row = new byte[values.Length];
    DisplayEncoding e = DisplayEncoding.ForRender(2.2);
    e.Encode(values, row);
    for (int i = 0; i < values.Length; i++)
      Assert.Equal(e.Encode(values[i]), row[i]);
    Assert.Throws<ArgumentException>(() => e.Encode(values, new byte[2]));
  }

  [Theory]
  [InlineData(2.2, Quantization.Truncate)]
  [InlineData(1.0, Quantization.Round)]
  [InlineData(0.45, Quantization.Round)]
  public void Span_variant_remembers_repeated_values_without_changing_a_byte(double gamma, Quantization quantization)
  {
    // Repeats (a background), values that share a memo slot, NaNs of other bit patterns, negatives, values past 1,
    // and neighbours one float apart, where a wrong memo hit would give a wrong byte.
    var random = new Random(311);
    var values = new float[50_000];
    float[] pool = new float[3000];
    for (int i = 0; i < pool.Length; i++)
      pool[i] = (float)(random.NextDouble() * 1.2 - 0.1);
    for (int i = 0; i < values.Length; i++)
      values[i] = (i % 7) switch
      {
        0 => 0.25f,
        1 => pool[random.Next(pool.Length)],
        2 => BitConverter.UInt32BitsToSingle(0x7FC00000u | (uint)random.Next(1 << 22)),
        3 => BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(pool[random.Next(100)]) + random.Next(-2, 3)),
        4 => float.NaN,
        _ => (float)random.NextDouble(),
      };
    var e = new DisplayEncoding(gamma, quantization);
    var bytes = new byte[values.Length];
    e.Encode(values, bytes);
    for (int i = 0; i < values.Length; i++)
      Assert.True(e.Encode(values[i]) == bytes[i], $"value {values[i]:R} at {i}");
  }

  [Fact]
  public void Image_encoding_equals_the_old_entry_points()
  {
    FloatImage img = new(5, 3, 3);
    var rnd = new Random(3);
    for (int i = 0; i < img.Data.Length; i++)
      img.Data[i] = (float)(rnd.NextDouble() * 1.2 - 0.1);
    Assert.Equal(Rgb8Image.FromFloatImage(img, 2.2, Quantization.Truncate).Data, DisplayEncoding.ForRender(2.2).Encode(img).Data);
    Assert.Equal(RenderSetup.ToDisplayImage(img, 2.2).Data, DisplayEncoding.ForRender(2.2).Encode(img).Data);
    Assert.Equal(Rgb8Image.FromFloatImage(img, 1.0).Data, DisplayEncoding.LinearRound.Encode(img).Data);
  }

  [Fact]
  public void Gray_image_is_replicated_and_other_band_counts_are_refused()
  {
    FloatImage gray = new(1, 1, 1);
    gray.Data[0] = 0.5f;
    Assert.Equal(new byte[] { 127, 127, 127 }, DisplayEncoding.ForRender(1.0).Encode(gray).Data);
    Assert.Throws<ArgumentException>(() => DisplayEncoding.ForRender(1.0).Encode(new FloatImage(1, 1, 2)));
  }

  [Theory]
  [InlineData(0.0)]
  [InlineData(double.NaN)]
  [InlineData(double.PositiveInfinity)]
  public void Explicit_gamma_must_be_positive_and_finite(double gamma) =>
    Assert.Throws<ArgumentOutOfRangeException>(() => new DisplayEncoding(gamma, Quantization.Round));

  [Theory]
  [InlineData(2.2, Quantization.Truncate)]
  [InlineData(1.0, Quantization.Truncate)]
  [InlineData(1.0, Quantization.Round)]
  [InlineData(2.4, Quantization.Round)]
  [InlineData(0.45, Quantization.Round)]
  [InlineData(0.05, Quantization.Truncate)]
  public void An_image_s_worth_of_values_gets_the_bytes_of_the_value_by_value_encoding(double gamma, Quantization quantization)
  {
    // Large enough for the step table: every float next to every step of the encoding (found here by bisection on the
    // value-by-value rule), whole runs of 2^15 consecutive floats (one table bucket) at random, and random values with
    // the specials.
    var e = new DisplayEncoding(gamma, quantization);
    var values = new System.Collections.Generic.List<float>();
    for (int k = 1; k <= 255; k++)
    {
      uint from = 0, to = 0x3F800000u;   // Encode(from) < k <= Encode(to) = 255
      if (e.Encode(BitConverter.UInt32BitsToSingle(from)) >= k)
        continue;
      while (to - from > 1)
      {
        uint mid = from + (to - from) / 2;
        if (e.Encode(BitConverter.UInt32BitsToSingle(mid)) >= k)
          to = mid;
        else
          from = mid;
      }
      for (uint bits = to - 4; bits <= to + 4; bits++)
        values.Add(BitConverter.UInt32BitsToSingle(bits));
    }
    var random = new Random(17);
    for (int run = 0; run < 12; run++)
    {
      uint first = (uint)random.Next(0x3F800000 >> 15) << 15;
      for (uint bits = first; bits < first + (1u << 15); bits++)
        values.Add(BitConverter.UInt32BitsToSingle(bits));
    }
    values.AddRange([0f, -0f, 1f, float.Epsilon, BitConverter.UInt32BitsToSingle(0x3F7FFFFFu), float.NaN, -1f, 2f]);
    while (values.Count < 1 << 19)
      values.Add(BitConverter.UInt32BitsToSingle((uint)random.Next(0x3F800000)));

    byte[] bytes = new byte[values.Count];
    e.Encode(values.ToArray(), bytes);
    for (int i = 0; i < bytes.Length; i++)
      if (bytes[i] != e.Encode(values[i]))
        Assert.Fail($"value {values[i]:R} (bits 0x{BitConverter.SingleToUInt32Bits(values[i]):X8}): {bytes[i]}, not {e.Encode(values[i])}");
  }
}
