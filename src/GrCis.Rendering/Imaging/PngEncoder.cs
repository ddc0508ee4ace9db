using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Linq;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace Rendering.Imaging;

/// <summary>
/// Writes non-interlaced 8-bit RGB / RGBA PNG files. Each scanline gets the filter whose output has the
/// smallest sum of absolute (signed) bytes, the heuristic libpng uses. No colour-space chunks are written,
/// so viewers treat the bytes as sRGB, like the original GrCis bitmaps.
/// </summary>
public sealed class PngEncoder
{
  // Larger IDAT chunks gain nothing; this keeps each chunk small enough for streaming readers.
  private const int MaxIdatLength = 1 << 16;

  private static readonly byte[] Signature = [137, 80, 78, 71, 13, 10, 26, 10];

  /// <summary>An encoder with default settings (CompressionLevel.Optimal, adaptive filters).</summary>
  public static PngEncoder Default { get; } = new();

  private readonly CompressionLevel _compressionLevel = CompressionLevel.Optimal;
  private readonly int _forcedFilter = -1;

  /// <summary>
  /// Deflate effort. Optimal is the default: on the five 640x480 GrCis reference renders it took ~20 ms
  /// per image, SmallestSize was 4% smaller but 4x slower, Fastest 58% larger and no faster
  /// (filter selection dominates at that level).
  /// </summary>
  public CompressionLevel CompressionLevel
  {
    get => _compressionLevel;
    init
    {
      if (!Enum.IsDefined(value))
        throw new ArgumentOutOfRangeException(nameof(value), value, "Unknown compression level.");
      _compressionLevel = value;
    }
  }

  /// <summary>Uses one filter type (0..4) for every row instead of choosing per row; -1 = adaptive. For tests.</summary>
  internal int ForcedFilter
  {
    get => _forcedFilter;
    init
    {
      if (value < -1 || value > PngFilter.Paeth)
        throw new ArgumentOutOfRangeException(nameof(value), value, "Filter must be -1 (adaptive) or 0..4.");
      _forcedFilter = value;
    }
  }

  /// <summary>The bytes of the PNG file of <paramref name="image"/>.</summary>
  public byte[] Encode(Rgb8Image image)
  {
    using MemoryStream ms = new();
    Encode(image, ms);
    return ms.ToArray();
  }

  /// <summary>Writes <paramref name="image"/> to <paramref name="output"/> as a PNG file.</summary>
  /// <exception cref="ArgumentNullException"><paramref name="image"/> is null.</exception>
  public void Encode(Rgb8Image image, Stream output)
  {
    ArgumentNullException.ThrowIfNull(image);
    EncodeRgb(image.Data, image.Width, image.Height, output);
  }

  /// <summary>
  /// Writes <paramref name="image"/> with text entries, each an uncompressed <c>iTXt</c> chunk (UTF-8 text)
  /// placed before the image data, where readers of metadata look first. The pixels are those of
  /// <see cref="Encode(Rgb8Image, Stream)"/>; only the chunks are added.
  /// </summary>
  /// <param name="image">The pixels.</param>
  /// <param name="output">Where the file goes.</param>
  /// <param name="text">Keyword and text pairs; a keyword is 1 to 79 printable Latin-1 characters without
  /// leading, trailing or double spaces (the PNG rule).</param>
  /// <exception cref="ArgumentException">A keyword breaks the PNG rule.</exception>
  public void Encode(Rgb8Image image, Stream output, IEnumerable<KeyValuePair<string, string>> text)
  {
    ArgumentNullException.ThrowIfNull(image);
    ArgumentNullException.ThrowIfNull(text);
    byte[][] chunks = text.Select(t => TextChunk(t.Key, t.Value)).ToArray();
    EncodePacked(image.Data, image.Width, image.Height, 3, 2, output, chunks);
  }

  /// <summary>Quantizes a linear framebuffer with <see cref="Rgb8Image.FromFloatImage"/> and encodes it.</summary>
  public void Encode(FloatImage image, double gamma, Stream output) =>
    Encode(Rgb8Image.FromFloatImage(image, gamma), output);

  /// <summary>Encodes tightly packed RGB bytes (3 per pixel, top row first).</summary>
  public void EncodeRgb(ReadOnlySpan<byte> rgb, int width, int height, Stream output) =>
    EncodePacked(rgb, width, height, 3, 2, output);

  /// <summary>Encodes tightly packed RGBA bytes (4 per pixel, straight alpha, top row first).</summary>
  public void EncodeRgba(ReadOnlySpan<byte> rgba, int width, int height, Stream output) =>
    EncodePacked(rgba, width, height, 4, 6, output);

  private void EncodePacked(ReadOnlySpan<byte> pixels, int width, int height, int channels, byte colorType, Stream output,
    IReadOnlyList<byte[]>? textChunks = null)
  {
    ArgumentNullException.ThrowIfNull(output);
    if (width <= 0 || height <= 0)
      throw new ArgumentOutOfRangeException(width <= 0 ? nameof(width) : nameof(height), $"Image size {width}x{height} must be positive.");
    long expected = (long)width * height * channels;
    if (pixels.Length != expected)
      throw new ArgumentException($"Pixel buffer has {pixels.Length} bytes but {width}x{height} with {channels} channels needs {expected}.", nameof(pixels));
    WritePng(output, width, height, 8, colorType, pixels, ReadOnlySpan<byte>.Empty, textChunks);
  }

  /// <summary>The data of an <c>iTXt</c> chunk: keyword, no compression, no language, UTF-8 text.</summary>
  internal static byte[] TextChunk(string keyword, string text)
  {
    ArgumentNullException.ThrowIfNull(keyword);
    ArgumentNullException.ThrowIfNull(text);
    bool valid = keyword.Length is >= 1 and <= 79 && keyword[0] != ' ' && keyword[^1] != ' ' && !keyword.Contains("  ", StringComparison.Ordinal) &&
      keyword.All(c => c is >= ' ' and <= '~' or >= '\u00a1' and <= '\u00ff');
    if (!valid)
      throw new ArgumentException($"PNG text keyword '{keyword}' must be 1 to 79 printable Latin-1 characters without leading, trailing or double spaces.", nameof(keyword));
    byte[] body = Encoding.UTF8.GetBytes(text);
    byte[] data = new byte[keyword.Length + 5 + body.Length];
    Encoding.Latin1.GetBytes(keyword, data);
    // After the keyword: its NUL, compression flag 0, method 0, empty language tag and translated keyword (two NULs).
    body.CopyTo(data, keyword.Length + 5);
    return data;
  }

  /// <summary>
  /// General writer: <paramref name="scanlines"/> holds height rows of packed samples (no filter bytes),
  /// each ceil(width * channels * bitDepth / 8) bytes, 16-bit samples big-endian. Tests use it to build
  /// gray, palette and 16-bit files; it does not validate the depth/colour-type combination.
  /// </summary>
  internal void WritePng(Stream output, int width, int height, byte bitDepth, byte colorType,
    ReadOnlySpan<byte> scanlines, ReadOnlySpan<byte> palette, IReadOnlyList<byte[]>? textChunks = null)
  {
    int channels = colorType switch { 0 => 1, 2 => 3, 3 => 1, 4 => 2, 6 => 4, _ => throw new ArgumentOutOfRangeException(nameof(colorType)) };
    int bitsPerPixel = channels * bitDepth;
    int rowBytes = checked((int)(((long)width * bitsPerPixel + 7) / 8));
    int bpp = Math.Max(1, bitsPerPixel / 8);
    if (scanlines.Length != (long)rowBytes * height)
      throw new ArgumentException($"Scanline buffer has {scanlines.Length} bytes, expected {(long)rowBytes * height}.", nameof(scanlines));

    Span<byte> ihdr = stackalloc byte[13];
    BinaryPrimitives.WriteInt32BigEndian(ihdr, width);
    BinaryPrimitives.WriteInt32BigEndian(ihdr[4..], height);
    ihdr[8] = bitDepth;
    ihdr[9] = colorType;
    ihdr[10] = 0; // deflate
    ihdr[11] = 0; // adaptive filtering
    ihdr[12] = 0; // no interlace

    output.Write(Signature);
    WriteChunk(output, "IHDR", ihdr);
    if (!palette.IsEmpty)
      WriteChunk(output, "PLTE", palette);
    foreach (byte[] chunk in textChunks ?? [])
      WriteChunk(output, "iTXt", chunk);

    using MemoryStream compressed = new();
    using (ZLibStream zlib = new(compressed, _compressionLevel, leaveOpen: true))
    {
      byte[] filtered = new byte[5 * (rowBytes + 1)];
      byte[] zeros = new byte[rowBytes];
      for (int y = 0; y < height; y++)
      {
        ReadOnlySpan<byte> row = scanlines.Slice(y * rowBytes, rowBytes);
        ReadOnlySpan<byte> prior = y == 0 ? zeros : scanlines.Slice((y - 1) * rowBytes, rowBytes);
        zlib.Write(FilterRow(row, prior, bpp, filtered, rowBytes));
      }
    }

    ReadOnlySpan<byte> idat = compressed.GetBuffer().AsSpan(0, (int)compressed.Length);
    do
    {
      int n = Math.Min(idat.Length, MaxIdatLength);
      WriteChunk(output, "IDAT", idat[..n]);
      idat = idat[n..];
    }
    while (!idat.IsEmpty);
    WriteChunk(output, "IEND", ReadOnlySpan<byte>.Empty);
  }

  /// <summary>Returns the filter byte followed by the filtered row, as a slice of <paramref name="scratch"/>.</summary>
  private ReadOnlySpan<byte> FilterRow(ReadOnlySpan<byte> row, ReadOnlySpan<byte> prior, int bpp, byte[] scratch, int rowBytes)
  {
    int stride = rowBytes + 1;
    if (_forcedFilter >= 0)
    {
      Span<byte> dest = scratch.AsSpan(0, stride);
      dest[0] = (byte)_forcedFilter;
      PngFilter.Apply((byte)_forcedFilter, row, prior, bpp, dest[1..]);
      return dest;
    }

    int best = 0;
    long bestCost = long.MaxValue;
    for (byte type = PngFilter.None; type <= PngFilter.Paeth; type++)
    {
      Span<byte> dest = scratch.AsSpan(type * stride, stride);
      dest[0] = type;
      PngFilter.Apply(type, row, prior, bpp, dest[1..]);
      long cost = PngFilter.Cost(dest[1..]);
      if (cost < bestCost)
      {
        bestCost = cost;
        best = type;
      }
    }
    return scratch.AsSpan(best * stride, stride);
  }

  private static void WriteChunk(Stream output, string type, ReadOnlySpan<byte> data)
  {
    Span<byte> header = stackalloc byte[8];
    BinaryPrimitives.WriteInt32BigEndian(header, data.Length);
    Encoding.ASCII.GetBytes(type, header[4..]);
    uint crc = Crc32.Update(Crc32.Start, header[4..]);
    crc = Crc32.Finish(Crc32.Update(crc, data));
    Span<byte> trailer = stackalloc byte[4];
    BinaryPrimitives.WriteUInt32BigEndian(trailer, crc);
    output.Write(header);
    output.Write(data);
    output.Write(trailer);
  }
}
