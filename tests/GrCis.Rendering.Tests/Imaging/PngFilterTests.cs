using System;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>
/// The scanline filters and their cost, sixteen bytes at a time, against the PNG specification's per-byte definitions
/// (written out here): the same bytes and the same sums, so the encoder picks the same filter per row and writes the
/// same file.
/// </summary>
public class PngFilterTests
{
  static byte Left(ReadOnlySpan<byte> row, int i, int bpp) => i >= bpp ? row[i - bpp] : (byte)0;

  static byte[] Reference(byte type, byte[] row, byte[] prior, int bpp)
  {
    var dest = new byte[row.Length];
    for (int i = 0; i < row.Length; i++)
    {
      int a = Left(row, i, bpp), b = prior[i], c = Left(prior, i, bpp);
      int predicted = type switch
      {
        PngFilter.None => 0,
        PngFilter.Sub => a,
        PngFilter.Up => b,
        PngFilter.Average => (a + b) / 2,
        _ => Paeth(a, b, c),
      };
      dest[i] = (byte)(row[i] - predicted);
    }
    return dest;
  }

  static int Paeth(int a, int b, int c)
  {
    int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
  }

  static long ReferenceCost(byte[] filtered)
  {
    long sum = 0;
    foreach (byte x in filtered)
      sum += Math.Abs((int)(sbyte)x);
    return sum;
  }

  /// <summary>Random bytes, with runs of the edge values (0, 1, 127, 128, 129, 255) where differences wrap or tie.</summary>
  static byte[] Bytes(Random random, int length)
  {
    byte[] edges = [0, 1, 127, 128, 129, 255];
    var bytes = new byte[length];
    random.NextBytes(bytes);
    if (random.Next(3) == 0)
      for (int i = 0; i < length; i++)
        bytes[i] = edges[random.Next(edges.Length)];
    return bytes;
  }

  [Fact]
  public void Every_filter_gives_the_per_byte_definition_for_every_length_and_pixel_size()
  {
    var random = new Random(2611);
    for (int bpp = 1; bpp <= 8; bpp++)
      for (int length = 0; length <= 80; length++)
        for (int trial = 0; trial < 4; trial++)
        {
          byte[] row = Bytes(random, length);
          // The first row's prior is all zeros.
          byte[] prior = trial == 0 ? new byte[length] : Bytes(random, length);
          for (byte type = PngFilter.None; type <= PngFilter.Paeth; type++)
          {
            var dest = new byte[length];
            PngFilter.Apply(type, row, prior, bpp, dest);
            Assert.True(Reference(type, row, prior, bpp).AsSpan().SequenceEqual(dest), $"filter {type}, bpp {bpp}, length {length}, trial {trial}");
          }
        }
  }

  [Fact]
  public void Paeth_ties_and_wrapping_differences_take_the_specifications_choice()
  {
    // Every (a, b, c) over byte values that include the ties (pa = pb, pa = pc, pb = pc) and both ends. With 16 bytes
    // per pixel, a 32-byte row puts 16 triples in one vector step: a = row[j], c = prior[j], b = prior[16 + j].
    byte[] values = [0, 1, 2, 63, 64, 127, 128, 129, 191, 254, 255];
    var triples = new System.Collections.Generic.List<(byte A, byte B, byte C)>();
    foreach (byte a in values)
      foreach (byte b in values)
        foreach (byte c in values)
          triples.Add((a, b, c));
    var random = new Random(27);
    for (int first = 0; first < triples.Count; first += 16)
    {
      var row = new byte[32];
      var prior = new byte[32];
      random.NextBytes(row);
      for (int j = 0; j < 16 && first + j < triples.Count; j++)
        (row[j], prior[16 + j], prior[j]) = triples[first + j];
      var dest = new byte[32];
      PngFilter.Apply(PngFilter.Paeth, row, prior, 16, dest);
      Assert.Equal(Reference(PngFilter.Paeth, row, prior, 16), dest);
    }
  }

  [Fact]
  public void Cost_is_the_sum_of_the_signed_magnitudes_for_every_length()
  {
    var random = new Random(1127);
    for (int length = 0; length <= 300; length++)
    {
      byte[] filtered = Bytes(random, length);
      Assert.Equal(ReferenceCost(filtered), PngFilter.Cost(filtered));
    }
    // Long rows of the largest magnitude: more steps than the sixteen-bit lanes hold without a flush.
    foreach (int length in new[] { 16 * 255, 16 * 255 + 1, 16 * 256, 16 * 600 + 7, 65536 })
    {
      var worst = new byte[length];
      Array.Fill(worst, (byte)128);
      Assert.Equal(128L * length, PngFilter.Cost(worst));
      Array.Fill(worst, (byte)129);   // −127
      Assert.Equal(127L * length, PngFilter.Cost(worst));
    }
  }
}
