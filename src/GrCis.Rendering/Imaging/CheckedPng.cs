using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace Rendering.Imaging;

/// <summary>
/// A PNG file read with the checks a viewer may skip: the signature, every chunk's CRC-32, the chunk order
/// (IHDR first, the IDAT chunks together, IEND last with nothing after it), and, in <see cref="Decode"/>,
/// the zlib stream's Adler-32 and its exact length. StbImageSharp (<see cref="ImageFile"/>) checks none of
/// these, so there a flipped bit in the image data decodes as a slightly wrong picture; here it is an error.
/// Also gives the file's text entries (<c>tEXt</c>, uncompressed <c>iTXt</c>), such as those
/// <see cref="PngFile.Save(string, Rgb8Image, IReadOnlyList{KeyValuePair{string, string}})"/> writes.
/// </summary>
public sealed class CheckedPng
{
  static readonly byte[] Signature = [137, 80, 78, 71, 13, 10, 26, 10];

  // Deflate cannot expand data more than about 1032 to 1: a header declaring more pixels than its
  // compressed data can hold is refused before the pixel buffer is allocated.
  const long MaxInflateRatio = 1100;

  readonly byte[] bytes;
  readonly List<(int Start, int Length)> idat;
  readonly string? path;

  CheckedPng(byte[] bytes, string? path)
  {
    this.bytes = bytes;
    this.path = path;
    idat = [];
    var text = new Dictionary<string, string>(StringComparer.Ordinal);
    Text = text;
    try
    {
      Walk(text);
    }
    catch (InvalidDataException e) when (path != null)
    {
      throw new InvalidDataException($"{path}: {e.Message}", e);
    }
  }

  /// <summary>Width in pixels.</summary>
  public int Width { get; private set; }

  /// <summary>Height in pixels.</summary>
  public int Height { get; private set; }

  /// <summary>Bits per sample (1, 2, 4, 8 or 16).</summary>
  public int BitDepth { get; private set; }

  /// <summary>The PNG colour type: 0 gray, 2 RGB, 3 palette, 4 gray and alpha, 6 RGBA.</summary>
  public int ColorType { get; private set; }

  /// <summary>True for an Adam7-interlaced file.</summary>
  public bool Interlaced { get; private set; }

  /// <summary>The text entries by keyword (the first of a repeated keyword); compressed text is not read.</summary>
  public IReadOnlyDictionary<string, string> Text { get; }

  /// <summary>Reads and checks the file's structure (not yet its image data: <see cref="Decode"/>).</summary>
  /// <param name="path">The file.</param>
  /// <param name="maxLength">A longer file is refused without being read.</param>
  /// <exception cref="InvalidDataException">Not a whole, intact PNG file; the message starts with the path.</exception>
  /// <exception cref="IOException">The file cannot be read.</exception>
  public static CheckedPng Read(string path, long maxLength = int.MaxValue)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read);
    long length = stream.Length;
    if (length > maxLength || length > Array.MaxLength)
      throw new InvalidDataException($"{path}: {length} bytes, more than the {Math.Min(maxLength, Array.MaxLength)} expected");
    byte[] data = new byte[length];
    int read = stream.ReadAtLeast(data, data.Length, throwOnEndOfStream: false);
    if (read != data.Length)
      throw new InvalidDataException($"{path}: the file shrank while it was read");
    return new CheckedPng(data, path);
  }

  /// <summary>Checks a file held in memory, as <see cref="Read"/> does; the messages carry no path.</summary>
  /// <exception cref="InvalidDataException">Not a whole, intact PNG file.</exception>
  public static CheckedPng Parse(byte[] data)
  {
    ArgumentNullException.ThrowIfNull(data);
    return new CheckedPng(data, null);
  }

  /// <summary>
  /// Inflates the image data, requiring its Adler-32 to match and exactly the bytes the header declares,
  /// and returns the pixels as RGB bytes (alpha dropped, gray replicated).
  /// </summary>
  /// <exception cref="InvalidDataException">Damaged image data; the message starts with the path when read from a file.</exception>
  public Rgb8Image Decode()
  {
    try
    {
      byte[] raw = Inflate();
      if (BitDepth == 8 && !Interlaced && ColorType is 2 or 6)
        return Unfilter(raw, ColorType == 2 ? 3 : 4);
      // The data is intact; other layouts are StbImageSharp's to decode.
      try
      {
        return ImageFile.DecodeRgb8(bytes);
      }
      catch (Exception e) when (e is not OutOfMemoryException and not InvalidDataException)
      {
        throw new InvalidDataException("corrupt or unsupported image", e);
      }
    }
    catch (InvalidDataException e) when (path != null)
    {
      throw new InvalidDataException($"{path}: {e.Message}", e);
    }
  }

  void Walk(Dictionary<string, string> text)
  {
    if (bytes.Length < Signature.Length || !bytes.AsSpan(0, Signature.Length).SequenceEqual(Signature))
      throw new InvalidDataException("not a PNG file (no PNG signature)");
    int at = Signature.Length;
    int chunks = 0;
    bool ended = false, palette = false;
    string previous = "";
    while (!ended)
    {
      if (bytes.Length - at < 12)
        throw new InvalidDataException(chunks == 0 ? "cut off after the signature" : $"cut off after chunk {previous} (no IEND)");
      uint declared = BinaryPrimitives.ReadUInt32BigEndian(bytes.AsSpan(at));
      string type = ChunkType(bytes.AsSpan(at + 4, 4), at);
      if (declared > int.MaxValue || declared > (uint)(bytes.Length - at - 12))
        throw new InvalidDataException($"cut off in chunk {type} at byte {at} ({declared} bytes declared, {Math.Max(0, bytes.Length - at - 12)} present)");
      int length = (int)declared;
      ReadOnlySpan<byte> data = bytes.AsSpan(at + 8, length);
      uint stored = BinaryPrimitives.ReadUInt32BigEndian(bytes.AsSpan(at + 8 + length));
      if (Crc32.Compute(bytes.AsSpan(at + 4, 4 + length)) != stored)
        throw new InvalidDataException($"CRC mismatch in chunk {type} at byte {at}: the chunk is damaged");

      if (chunks == 0 && type != "IHDR")
        throw new InvalidDataException($"first chunk is {type}, not IHDR");
      switch (type)
      {
        case "IHDR":
          if (chunks != 0)
            throw new InvalidDataException("a second IHDR chunk");
          Header(data);
          break;
        case "PLTE":
          palette = true;
          break;
        case "IDAT":
          if (idat.Count > 0 && previous != "IDAT")
            throw new InvalidDataException($"IDAT chunks split by {previous} at byte {at}");
          idat.Add((at + 8, length));
          break;
        case "IEND":
          if (length != 0)
            throw new InvalidDataException("IEND chunk is not empty");
          ended = true;
          break;
        case "tEXt":
          ReadText(data, text, international: false);
          break;
        case "iTXt":
          ReadText(data, text, international: true);
          break;
        default:
          // Bit 5 of the first letter clear: a critical chunk, which a decoder must understand.
          if ((bytes[at + 4] & 0x20) == 0)
            throw new InvalidDataException($"unknown critical chunk {type} at byte {at}");
          break;
      }
      previous = type;
      chunks++;
      at += 12 + length;
    }
    if (at != bytes.Length)
      throw new InvalidDataException($"{bytes.Length - at} bytes after IEND");
    if (idat.Count == 0)
      throw new InvalidDataException("no image data (no IDAT chunk)");
    if (ColorType == 3 && !palette)
      throw new InvalidDataException("a palette image without a PLTE chunk");
  }

  static string ChunkType(ReadOnlySpan<byte> type, int at)
  {
    foreach (byte b in type)
      if (!(b is >= (byte)'A' and <= (byte)'Z' or >= (byte)'a' and <= (byte)'z'))
        throw new InvalidDataException($"damaged chunk header at byte {at} (the type is not four letters)");
    return Encoding.ASCII.GetString(type);
  }

  void Header(ReadOnlySpan<byte> data)
  {
    if (data.Length != 13)
      throw new InvalidDataException($"IHDR chunk has {data.Length} bytes, not 13");
    uint width = BinaryPrimitives.ReadUInt32BigEndian(data), height = BinaryPrimitives.ReadUInt32BigEndian(data[4..]);
    if (width == 0 || height == 0 || width > int.MaxValue || height > int.MaxValue || (long)width * height > Rgb8Image.MaxPixels)
      throw new InvalidDataException($"declared size {width}x{height} is out of range");
    int depth = data[8], color = data[9];
    bool valid = color switch
    {
      0 => depth is 1 or 2 or 4 or 8 or 16,
      3 => depth is 1 or 2 or 4 or 8,
      2 or 4 or 6 => depth is 8 or 16,
      _ => false,
    };
    if (!valid)
      throw new InvalidDataException($"bit depth {depth} with colour type {color} is not a PNG format");
    if (data[10] != 0 || data[11] != 0 || data[12] > 1)
      throw new InvalidDataException("unknown compression, filter or interlace method in IHDR");
    Width = (int)width;
    Height = (int)height;
    BitDepth = depth;
    ColorType = color;
    Interlaced = data[12] == 1;
  }

  static void ReadText(ReadOnlySpan<byte> data, Dictionary<string, string> text, bool international)
  {
    int end = data.IndexOf((byte)0);
    if (end < 1 || end > 79)
      return; // A malformed entry is not ours to read; its CRC already held, so the file itself is intact.
    string keyword = Encoding.Latin1.GetString(data[..end]);
    ReadOnlySpan<byte> rest = data[(end + 1)..];
    string value;
    if (!international)
      value = Encoding.Latin1.GetString(rest);
    else
    {
      // Compression flag and method, then a language tag and a translated keyword, each ended by NUL.
      if (rest.Length < 2 || rest[0] != 0)
        return;
      rest = rest[2..];
      for (int field = 0; field < 2; field++)
      {
        int nul = rest.IndexOf((byte)0);
        if (nul < 0)
          return;
        rest = rest[(nul + 1)..];
      }
      value = Encoding.UTF8.GetString(rest);
    }
    text.TryAdd(keyword, value);
  }

  int Channels => ColorType switch { 0 => 1, 2 => 3, 3 => 1, 4 => 2, _ => 4 };

  long RowBytes(long width) => (width * Channels * BitDepth + 7) / 8;

  /// <summary>The length of the filtered scanlines the header declares (all seven passes when interlaced).</summary>
  long RawLength()
  {
    if (!Interlaced)
      return Height * (1 + RowBytes(Width));
    ReadOnlySpan<int> x0 = [0, 4, 0, 2, 0, 1, 0], dx = [8, 8, 4, 4, 2, 2, 1], y0 = [0, 0, 4, 0, 2, 0, 1], dy = [8, 8, 8, 4, 4, 2, 2];
    long total = 0;
    for (int p = 0; p < 7; p++)
    {
      long w = (Width - x0[p] + dx[p] - 1) / dx[p], h = (Height - y0[p] + dy[p] - 1) / dy[p];
      if (w > 0 && h > 0)
        total += h * (1 + RowBytes(w));
    }
    return total;
  }

  byte[] Inflate()
  {
    long compressedLength = 0;
    foreach ((_, int length) in idat)
      compressedLength += length;
    long expected = RawLength();
    if (expected > Array.MaxLength || expected > compressedLength * MaxInflateRatio + 1024)
      throw new InvalidDataException($"declared size {Width}x{Height} needs more image data than the file's {compressedLength} bytes can hold");
    if (compressedLength < 6)
      throw new InvalidDataException("image data too short for a zlib stream");

    byte[] compressed = new byte[compressedLength];
    int filled = 0;
    foreach ((int start, int length) in idat)
    {
      Buffer.BlockCopy(bytes, start, compressed, filled, length);
      filled += length;
    }

    byte[] raw = new byte[expected];
    int got;
    bool more;
    try
    {
      using var zlib = new ZLibStream(new MemoryStream(compressed), CompressionMode.Decompress);
      got = zlib.ReadAtLeast(raw, raw.Length, throwOnEndOfStream: false);
      more = got == raw.Length && zlib.Read(new byte[1]) != 0;
    }
    catch (InvalidDataException e)
    {
      // The runtime's message names an "unsupported compression method" even for a checksum failure.
      throw new InvalidDataException("damaged image data (zlib: invalid deflate data or an Adler-32 mismatch)", e);
    }
    if (more)
      throw new InvalidDataException("more image data than the header declares");
    if (got != raw.Length)
      throw new InvalidDataException($"image data ends early ({got} of {raw.Length} bytes)");
    // The stream's own checksum, checked here too: the runtime's inflater may stop without reading it.
    uint stored = BinaryPrimitives.ReadUInt32BigEndian(compressed.AsSpan(compressed.Length - 4));
    if (Adler32(raw) != stored)
      throw new InvalidDataException("damaged image data (zlib: Adler-32 mismatch)");
    return raw;
  }

  static uint Adler32(ReadOnlySpan<byte> data)
  {
    const uint Mod = 65521;
    uint a = 1, b = 0;
    while (!data.IsEmpty)
    {
      // 5552 bytes is the most that cannot overflow b before the modulo (zlib's NMAX).
      int n = Math.Min(data.Length, 5552);
      foreach (byte x in data[..n])
      {
        a += x;
        b += a;
      }
      a %= Mod;
      b %= Mod;
      data = data[n..];
    }
    return b << 16 | a;
  }

  Rgb8Image Unfilter(byte[] raw, int channels)
  {
    int stride = Width * channels;
    var image = new Rgb8Image(Width, Height);
    byte[] prior = new byte[stride];
    byte[] row = new byte[stride];
    for (int y = 0; y < Height; y++)
    {
      int start = y * (stride + 1);
      raw.AsSpan(start + 1, stride).CopyTo(row);
      if (!PngFilter.Undo(raw[start], row, prior, channels))
        throw new InvalidDataException($"unknown filter type {raw[start]} in row {y}");
      Span<byte> target = image.Data.AsSpan(y * Width * 3, Width * 3);
      if (channels == 3)
        row.CopyTo(target);
      else
        for (int x = 0; x < Width; x++)
        {
          target[3 * x] = row[4 * x];
          target[3 * x + 1] = row[4 * x + 1];
          target[3 * x + 2] = row[4 * x + 2];
        }
      (prior, row) = (row, prior);
    }
    return image;
  }
}
