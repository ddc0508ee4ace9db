using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>
/// <see cref="CheckedPng"/> finds what StbImageSharp lets through (a flipped bit anywhere, a cut file, extra
/// bytes, a zlib stream that fails its checksum or does not fit the header), and reads back the text entries
/// <see cref="PngEncoder"/> writes without changing the pixels.
/// </summary>
public class CheckedPngTests
{
  static readonly KeyValuePair<string, string>[] Text = [new("GrCis frame", "frame 3\ntime 0.12\nnote ünïcode ✓"), new("Other", "x")];

  static byte[] Encode(Rgb8Image image, IEnumerable<KeyValuePair<string, string>> text)
  {
    using var ms = new MemoryStream();
    PngEncoder.Default.Encode(image, ms, text);
    return ms.ToArray();
  }

  static void WriteCrc(byte[] png, int chunk)
  {
    int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(chunk));
    BinaryPrimitives.WriteUInt32BigEndian(png.AsSpan(chunk + 8 + length), Crc32.Compute(png.AsSpan(chunk + 4, 4 + length)));
  }

  static void Rejected(byte[] png)
  {
    try
    {
      CheckedPng.Parse(png).Decode();
    }
    catch (InvalidDataException)
    {
      return;
    }
    Assert.Fail("accepted a damaged file");
  }

  [Fact]
  public void Text_entries_are_read_back_and_the_pixels_are_unchanged()
  {
    Rgb8Image image = PngTestFiles.RenderLikeImage(37, 21, 1);
    byte[] plain = PngEncoder.Default.Encode(image), tagged = Encode(image, Text);

    CheckedPng png = CheckedPng.Parse(tagged);
    Assert.Equal(Text.OrderBy(t => t.Key), png.Text.OrderBy(t => t.Key));
    Assert.Equal((37, 21, 8, 2, false), (png.Width, png.Height, png.BitDepth, png.ColorType, png.Interlaced));
    Assert.Equal(image.Data, png.Decode().Data);
    Assert.Equal(image.Data, TestDecode.Png(tagged).Data);
    // The same chunks as without text, the iTXt ones after IHDR and before the image data.
    Assert.Equal(new[] { "IHDR", "iTXt", "iTXt", "IDAT", "IEND" }, PngTestFiles.Chunks(tagged).Select(c => c.Type));
    Assert.Equal(new[] { "IHDR", "IDAT", "IEND" }, PngTestFiles.Chunks(plain).Select(c => c.Type));
    Assert.Empty(CheckedPng.Parse(plain).Text);
  }

  [Fact]
  public void Every_single_bit_flip_is_found()
  {
    byte[] good = Encode(PngTestFiles.RenderLikeImage(6, 4, 2), [new("GrCis frame", "frame 1")]);
    Assert.Equal(6 * 4 * 3, CheckedPng.Parse(good).Decode().Data.Length);
    for (int i = 0; i < good.Length; i++)
      for (int bit = 0; bit < 8; bit++)
      {
        byte[] bad = (byte[])good.Clone();
        bad[i] ^= (byte)(1 << bit);
        Rejected(bad);
      }
  }

  [Fact]
  public void A_flip_in_the_image_data_under_a_recomputed_crc_fails_the_zlib_checksum()
  {
    Rgb8Image image = PngTestFiles.RenderLikeImage(40, 30, 3);
    byte[] good = PngEncoder.Default.Encode(image);
    var idat = PngTestFiles.Chunks(good).Single(c => c.Type == "IDAT");
    int caught = 0;
    // Every byte of the deflate data and its Adler-32 (not the 2-byte zlib header), the chunk's CRC made valid again.
    for (int i = 2; i < idat.Length; i++)
    {
      byte[] bad = (byte[])good.Clone();
      bad[idat.Offset + 8 + i] ^= (byte)(1 << (i % 8));
      WriteCrc(bad, idat.Offset);
      CheckedPng png = CheckedPng.Parse(bad);
      try
      {
        // A flip of a padding bit after the last block changes nothing: the pixels must then be the same.
        Assert.Equal(image.Data, png.Decode().Data);
      }
      catch (InvalidDataException e)
      {
        Assert.Contains("image data", e.Message);
        caught++;
      }
    }
    Assert.True(caught >= idat.Length - 3, $"{caught} of {idat.Length - 2} flips found");
    // StbImageSharp does not check the Adler-32: such a file decodes there.
    byte[] quiet = (byte[])good.Clone();
    quiet[idat.Offset + 8 + idat.Length - 1] ^= 1;
    WriteCrc(quiet, idat.Offset);
    Assert.Equal(image.Data, TestDecode.Png(quiet).Data);
    Assert.Contains("Adler-32", Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(quiet).Decode()).Message);
  }

  [Fact]
  public void Every_truncation_and_extra_bytes_after_iend_are_found()
  {
    byte[] good = Encode(PngTestFiles.RenderLikeImage(9, 7, 4), Text);
    for (int n = 0; n < good.Length; n++)
      Rejected(good[..n]);
    Rejected([.. good, 0]);
    var e = Assert.Throws<InvalidDataException>(() => CheckedPng.Parse([.. good, 1, 2, 3]));
    Assert.Contains("3 bytes after IEND", e.Message);
  }

  [Fact]
  public void Image_data_that_does_not_fit_the_header_is_refused()
  {
    byte[] rows = new byte[4 * (1 + 3 * 4)];
    Assert.Equal(12, CheckedPng.Parse(PngTestFiles.FromFilteredRows(4, 4, 8, 2, rows)).Decode().Width * 3);
    var shorter = Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(PngTestFiles.FromFilteredRows(4, 4, 8, 2, rows[..^1])).Decode());
    Assert.Contains("ends early", shorter.Message);
    var longer = Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(PngTestFiles.FromFilteredRows(4, 4, 8, 2, [.. rows, 0])).Decode());
    Assert.Contains("more image data", longer.Message);
    byte[] badFilter = (byte[])rows.Clone();
    badFilter[13] = 9;
    Assert.Contains("filter type 9", Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(PngTestFiles.FromFilteredRows(4, 4, 8, 2, badFilter)).Decode()).Message);
    // A header that declares far more pixels than the data can inflate to: refused before allocating them.
    var huge = Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(PngTestFiles.FromFilteredRows(16000, 16000, 8, 2, rows)).Decode());
    Assert.Contains("needs more image data", huge.Message);
  }

  [Fact]
  public void Chunk_order_rules_hold()
  {
    byte[] z;
    using (var ms = new MemoryStream())
    {
      using (var zlib = new ZLibStream(ms, CompressionLevel.Optimal, leaveOpen: true))
        zlib.Write(new byte[2 * (1 + 3 * 2)]);
      z = ms.ToArray();
    }
    byte[] split = PngTestFiles.Assemble(2, 2, 8, 2, z, idatSplit: 3);
    Assert.Equal(2, CheckedPng.Parse(split).Decode().Height);

    // IDAT chunks split by another chunk.
    var chunks = PngTestFiles.Chunks(split);
    using var broken = new MemoryStream();
    broken.Write(split.AsSpan(0, chunks[2].Offset));
    PngTestFiles.WriteChunk(broken, "tEXt", "a\0b"u8);
    broken.Write(split.AsSpan(chunks[2].Offset));
    Assert.Contains("IDAT chunks split", Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(broken.ToArray())).Message);

    // An unknown critical chunk, and an unknown ancillary one (skipped).
    using var critical = new MemoryStream();
    critical.Write(split.AsSpan(0, chunks[1].Offset));
    PngTestFiles.WriteChunk(critical, "ZZZZ", "x"u8);
    critical.Write(split.AsSpan(chunks[1].Offset));
    Assert.Contains("unknown critical chunk ZZZZ", Assert.Throws<InvalidDataException>(() => CheckedPng.Parse(critical.ToArray())).Message);
    using var ancillary = new MemoryStream();
    ancillary.Write(split.AsSpan(0, chunks[1].Offset));
    PngTestFiles.WriteChunk(ancillary, "zzZz", "x"u8);
    PngTestFiles.WriteChunk(ancillary, "tEXt", [.. "Title\0Latin-1 "u8, 0xE9]);
    ancillary.Write(split.AsSpan(chunks[1].Offset));
    CheckedPng withText = CheckedPng.Parse(ancillary.ToArray());
    Assert.Equal("Latin-1 \u00e9", withText.Text["Title"]);
  }

  [Fact]
  public void Other_formats_are_checked_and_decoded_as_the_image_reader_does()
  {
    byte[] gray = PngTestFiles.Encode(5, 3, 8, 0, Enumerable.Range(0, 15).Select(i => (byte)(i * 17)).ToArray());
    Assert.Equal(TestDecode.Png(gray).Data, CheckedPng.Parse(gray).Decode().Data);
    byte[] palette = PngTestFiles.Encode(4, 2, 8, 3, [0, 1, 2, 1, 2, 0, 1, 1], [255, 0, 0, 0, 255, 0, 0, 0, 255]);
    Assert.Equal(TestDecode.Png(palette).Data, CheckedPng.Parse(palette).Decode().Data);
    Rgb8Image rgba = PngTestFiles.RandomImage(3, 3, 5);
    using var ms = new MemoryStream();
    byte[] withAlpha = Enumerable.Range(0, 9).SelectMany(i => new[] { rgba.Data[3 * i], rgba.Data[3 * i + 1], rgba.Data[3 * i + 2], (byte)255 }).ToArray();
    PngEncoder.Default.EncodeRgba(withAlpha, 3, 3, ms);
    Assert.Equal(rgba.Data, CheckedPng.Parse(ms.ToArray()).Decode().Data);
  }

  [Fact]
  public void A_file_is_named_in_every_message_and_a_long_one_is_not_read()
  {
    string path = Path.Combine(Path.GetTempPath(), "checked-png-" + Guid.NewGuid().ToString("N")[..8] + ".png");
    try
    {
      byte[] good = Encode(PngTestFiles.RenderLikeImage(8, 8, 6), Text);
      File.WriteAllBytes(path, good[..^5]);
      Assert.StartsWith(path + ": cut off", Assert.Throws<InvalidDataException>(() => CheckedPng.Read(path)).Message);
      File.WriteAllBytes(path, good);
      Assert.Equal(8, CheckedPng.Read(path).Decode().Width);
      Assert.StartsWith(path + ": ", Assert.Throws<InvalidDataException>(() => CheckedPng.Read(path, maxLength: 50)).Message);
    }
    finally
    {
      File.Delete(path);
    }
  }

  [Theory]
  [InlineData("")]
  [InlineData(" lead")]
  [InlineData("trail ")]
  [InlineData("two  spaces")]
  [InlineData("tab\there")]
  [InlineData("snow ☃")]
  public void A_keyword_the_PNG_rule_forbids_is_refused(string keyword) =>
    Assert.Throws<ArgumentException>(() => Encode(new Rgb8Image(1, 1), [new(keyword, "x")]));
}
