using System;
using System.Buffers.Binary;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace Rendering.Imaging;

/// <summary>
/// Decodes non-interlaced PNG files of every standard colour type and bit depth to 8-bit RGB.
/// Alpha and tRNS are dropped (not composited); 16-bit samples are rounded to 8 bits; ancillary
/// chunks (gAMA, sRGB, text, ...) are ignored. Anything corrupt or unsupported throws
/// <see cref="InvalidDataException"/> with a message saying what was wrong.
/// </summary>
public static class PngDecoder
{
  private static readonly byte[] Signature = [137, 80, 78, 71, 13, 10, 26, 10];

  public static Rgb8Image Decode(Stream stream)
  {
    ArgumentNullException.ThrowIfNull(stream);
    using MemoryStream ms = new();
    stream.CopyTo(ms);
    return Decode(ms.GetBuffer().AsSpan(0, (int)ms.Length));
  }

  public static Rgb8Image Decode(ReadOnlySpan<byte> png)
  {
    if (png.Length < Signature.Length || !png[..Signature.Length].SequenceEqual(Signature))
      throw new InvalidDataException("Not a PNG file: the 8-byte signature is missing.");

    Header? header = null;
    byte[]? palette = null;
    using MemoryStream idat = new();
    bool sawIend = false;
    int pos = Signature.Length;
    while (!sawIend)
    {
      if (png.Length - pos < 12)
        throw new InvalidDataException($"PNG is truncated at byte {pos}: no room for a chunk header (IEND missing).");
      uint length = BinaryPrimitives.ReadUInt32BigEndian(png[pos..]);
      ReadOnlySpan<byte> typeBytes = png.Slice(pos + 4, 4);
      string type = ChunkName(typeBytes);
      if (length > int.MaxValue || png.Length - pos - 12 < length)
        throw new InvalidDataException($"PNG is truncated: chunk {type} at byte {pos} declares {length} data bytes but the file ends first.");
      ReadOnlySpan<byte> data = png.Slice(pos + 8, (int)length);
      uint stored = BinaryPrimitives.ReadUInt32BigEndian(png[(pos + 8 + (int)length)..]);
      uint actual = Crc32.Finish(Crc32.Update(Crc32.Update(Crc32.Start, typeBytes), data));
      if (stored != actual)
        throw new InvalidDataException($"PNG chunk {type} at byte {pos} has a bad CRC (stored 0x{stored:X8}, computed 0x{actual:X8}).");
      pos += 12 + (int)length;

      if (header is null && type != "IHDR")
        throw new InvalidDataException($"PNG must start with an IHDR chunk, found {type}.");
      switch (type)
      {
        case "IHDR":
          if (header is not null)
            throw new InvalidDataException("PNG has more than one IHDR chunk.");
          header = Header.Parse(data);
          break;
        case "PLTE":
          if (data.Length == 0 || data.Length % 3 != 0 || data.Length > 768)
            throw new InvalidDataException($"PNG PLTE chunk has invalid length {data.Length} (must be a multiple of 3, 3..768).");
          if (idat.Length > 0)
            throw new InvalidDataException("PNG PLTE chunk appears after image data.");
          palette = data.ToArray();
          break;
        case "IDAT":
          idat.Write(data);
          break;
        case "IEND":
          sawIend = true;
          break;
        default:
          // Bit 5 of the first letter clear = critical chunk we cannot skip safely.
          if ((typeBytes[0] & 0x20) == 0)
            throw new InvalidDataException($"PNG has unsupported critical chunk {type}.");
          break;
      }
    }

    Header h = header!.Value;
    if (h.ColorType == 3 && palette is null)
      throw new InvalidDataException("Palette PNG (colour type 3) has no PLTE chunk.");
    if (idat.Length == 0)
      throw new InvalidDataException("PNG has no IDAT chunk.");

    byte[] raw = Inflate(idat, (long)(h.RowBytes + 1) * h.Height);
    Unfilter(raw, h);
    return ToRgb(raw, h, palette);
  }

  private static byte[] Inflate(MemoryStream idat, long expected)
  {
    if (expected > Array.MaxLength)
      throw new InvalidDataException($"PNG image data would need {expected} bytes, too large to decode.");
    byte[] raw = new byte[expected];
    idat.Position = 0;
    int filled = 0;
    try
    {
      using ZLibStream zlib = new(idat, CompressionMode.Decompress, leaveOpen: true);
      while (filled < raw.Length)
      {
        int n = zlib.Read(raw, filled, raw.Length - filled);
        if (n == 0)
          break;
        filled += n;
      }
    }
    catch (InvalidDataException ex)
    {
      throw new InvalidDataException($"PNG image data is not a valid zlib stream: {ex.Message}", ex);
    }
    if (filled < raw.Length)
      throw new InvalidDataException($"PNG image data is truncated: got {filled} of {raw.Length} decompressed bytes.");
    return raw;
  }

  private static void Unfilter(byte[] raw, Header h)
  {
    int stride = h.RowBytes + 1;
    int bpp = Math.Max(1, h.BitsPerPixel / 8);
    byte[] zeros = new byte[h.RowBytes];
    for (int y = 0; y < h.Height; y++)
    {
      byte type = raw[y * stride];
      Span<byte> row = raw.AsSpan(y * stride + 1, h.RowBytes);
      ReadOnlySpan<byte> prior = y == 0 ? zeros : raw.AsSpan((y - 1) * stride + 1, h.RowBytes);
      if (!PngFilter.Undo(type, row, prior, bpp))
        throw new InvalidDataException($"PNG row {y} has invalid filter type {type}.");
    }
  }

  private static Rgb8Image ToRgb(byte[] raw, Header h, byte[]? palette)
  {
    Rgb8Image image = new(h.Width, h.Height);
    byte[] dst = image.Data;
    int stride = h.RowBytes + 1;
    int channels = h.Channels;
    int depth = h.BitDepth;
    int paletteEntries = palette is null ? 0 : palette.Length / 3;
    for (int y = 0; y < h.Height; y++)
    {
      int rowStart = y * stride + 1;
      int o = y * h.Width * 3;
      for (int x = 0; x < h.Width; x++, o += 3)
      {
        if (h.ColorType == 3)
        {
          int index = ReadSample(raw, rowStart, x, depth);
          if (index >= paletteEntries)
            throw new InvalidDataException($"PNG pixel ({x}, {y}) uses palette index {index} but PLTE has {paletteEntries} entries.");
          dst[o] = palette![3 * index];
          dst[o + 1] = palette[3 * index + 1];
          dst[o + 2] = palette[3 * index + 2];
        }
        else if (channels <= 2)
        {
          // Gray or gray+alpha: the first sample is the gray level.
          byte g = To8Bit(ReadSample(raw, rowStart, x * channels, depth), depth);
          dst[o] = dst[o + 1] = dst[o + 2] = g;
        }
        else
        {
          int s = x * channels;
          dst[o] = To8Bit(ReadSample(raw, rowStart, s, depth), depth);
          dst[o + 1] = To8Bit(ReadSample(raw, rowStart, s + 1, depth), depth);
          dst[o + 2] = To8Bit(ReadSample(raw, rowStart, s + 2, depth), depth);
        }
      }
    }
    return image;
  }

  /// <summary>Reads sample number <paramref name="index"/> of a row; sub-byte samples are packed MSB first.</summary>
  private static int ReadSample(byte[] raw, int rowStart, int index, int depth)
  {
    switch (depth)
    {
      case 8:
        return raw[rowStart + index];
      case 16:
        return (raw[rowStart + 2 * index] << 8) | raw[rowStart + 2 * index + 1];
      default:
        int bit = index * depth;
        int shift = 8 - depth - (bit & 7);
        return (raw[rowStart + (bit >> 3)] >> shift) & ((1 << depth) - 1);
    }
  }

  private static byte To8Bit(int sample, int depth) => depth switch
  {
    8 => (byte)sample,
    // Exact round(v / 257): 257 is odd, so no ties.
    16 => (byte)((sample + 128) / 257),
    // Scale to full range: 1 -> 255, 2-bit 1 -> 85, 4-bit 1 -> 17.
    _ => (byte)(sample * 255 / ((1 << depth) - 1)),
  };

  private static string ChunkName(ReadOnlySpan<byte> type)
  {
    foreach (byte b in type)
    {
      if (!((b >= 'A' && b <= 'Z') || (b >= 'a' && b <= 'z')))
        return $"0x{BinaryPrimitives.ReadUInt32BigEndian(type):X8}";
    }
    return Encoding.ASCII.GetString(type);
  }

  private readonly record struct Header(int Width, int Height, int BitDepth, int ColorType)
  {
    public int Channels => ChannelsOf(ColorType);
    public int BitsPerPixel => Channels * BitDepth;

    private static int ChannelsOf(int colorType) => colorType switch { 0 => 1, 2 => 3, 3 => 1, 4 => 2, _ => 4 };

    private static int BitsPerPixelOf(int colorType, int depth) => ChannelsOf(colorType) * depth;
    public int RowBytes => (int)(((long)Width * BitsPerPixel + 7) / 8);

    public static Header Parse(ReadOnlySpan<byte> d)
    {
      if (d.Length != 13)
        throw new InvalidDataException($"PNG IHDR chunk has length {d.Length}, expected 13.");
      uint width = BinaryPrimitives.ReadUInt32BigEndian(d);
      uint height = BinaryPrimitives.ReadUInt32BigEndian(d[4..]);
      byte depth = d[8], colorType = d[9], compression = d[10], filter = d[11], interlace = d[12];
      if (width == 0 || height == 0 || width > int.MaxValue || height > int.MaxValue)
        throw new InvalidDataException($"PNG has invalid size {width}x{height}.");
      if ((long)width * height > Rgb8Image.MaxPixels)
        throw new InvalidDataException($"PNG size {width}x{height} exceeds the decoder limit of {Rgb8Image.MaxPixels} pixels.");
      bool depthOk = colorType switch
      {
        0 => depth is 1 or 2 or 4 or 8 or 16,
        3 => depth is 1 or 2 or 4 or 8,
        2 or 4 or 6 => depth is 8 or 16,
        _ => throw new InvalidDataException($"PNG has invalid colour type {colorType}."),
      };
      if (!depthOk)
        throw new InvalidDataException($"PNG colour type {colorType} does not allow bit depth {depth}.");
      long rowBytes = ((long)width * BitsPerPixelOf(colorType, depth) + 7) / 8;
      if ((rowBytes + 1) * height > Array.MaxLength)
        throw new InvalidDataException($"PNG size {width}x{height} at {depth} bits is too large to decode.");
      if (compression != 0)
        throw new InvalidDataException($"PNG has unknown compression method {compression}.");
      if (filter != 0)
        throw new InvalidDataException($"PNG has unknown filter method {filter}.");
      if (interlace == 1)
        throw new InvalidDataException("Interlaced (Adam7) PNG files are not supported; re-save without interlacing.");
      if (interlace != 0)
        throw new InvalidDataException($"PNG has unknown interlace method {interlace}.");
      return new Header((int)width, (int)height, depth, colorType);
    }
  }
}
