using System;
using System.Buffers.Binary;
using System.IO;
using System.IO.Compression;
using System.Text;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>Builds PNG byte streams by hand so decoder tests control every filter byte and chunk.</summary>
internal static class PngTestFiles
{
  public static readonly byte[] Signature = [137, 80, 78, 71, 13, 10, 26, 10];

  /// <summary>A PNG whose IDAT holds exactly <paramref name="filteredRows"/> (filter byte + row, per row).</summary>
  public static byte[] FromFilteredRows(int width, int height, byte bitDepth, byte colorType, byte[] filteredRows,
    byte[]? palette = null, byte interlace = 0, int idatSplit = int.MaxValue)
  {
    using MemoryStream z = new();
    using (ZLibStream zlib = new(z, CompressionLevel.Optimal, leaveOpen: true))
      zlib.Write(filteredRows);
    return Assemble(width, height, bitDepth, colorType, z.ToArray(), palette, interlace, idatSplit);
  }

  public static byte[] Assemble(int width, int height, byte bitDepth, byte colorType, byte[] zlibData,
    byte[]? palette = null, byte interlace = 0, int idatSplit = int.MaxValue)
  {
    using MemoryStream ms = new();
    ms.Write(Signature);
    byte[] ihdr = new byte[13];
    BinaryPrimitives.WriteInt32BigEndian(ihdr, width);
    BinaryPrimitives.WriteInt32BigEndian(ihdr.AsSpan(4), height);
    ihdr[8] = bitDepth;
    ihdr[9] = colorType;
    ihdr[12] = interlace;
    WriteChunk(ms, "IHDR", ihdr);
    if (palette is not null)
      WriteChunk(ms, "PLTE", palette);
    for (int i = 0; i < zlibData.Length; i += idatSplit)
      WriteChunk(ms, "IDAT", zlibData.AsSpan(i, Math.Min(idatSplit, zlibData.Length - i)));
    WriteChunk(ms, "IEND", ReadOnlySpan<byte>.Empty);
    return ms.ToArray();
  }

  /// <summary>Encodes packed scanlines with the library's encoder (adaptive filters) at any depth/colour type.</summary>
  public static byte[] Encode(int width, int height, byte bitDepth, byte colorType, byte[] scanlines, byte[]? palette = null)
  {
    using MemoryStream ms = new();
    PngEncoder.Default.WritePng(ms, width, height, bitDepth, colorType, scanlines, palette ?? []);
    return ms.ToArray();
  }

  public static void WriteChunk(Stream s, string type, ReadOnlySpan<byte> data)
  {
    byte[] header = new byte[8];
    BinaryPrimitives.WriteInt32BigEndian(header, data.Length);
    Encoding.ASCII.GetBytes(type, header.AsSpan(4));
    uint crc = Crc32.Finish(Crc32.Update(Crc32.Update(Crc32.Start, header.AsSpan(4)), data));
    s.Write(header);
    s.Write(data);
    byte[] trailer = new byte[4];
    BinaryPrimitives.WriteUInt32BigEndian(trailer, crc);
    s.Write(trailer);
  }

  /// <summary>Offsets of every chunk: (start of length field, type, data length).</summary>
  public static (int Offset, string Type, int Length)[] Chunks(byte[] png)
  {
    var list = new System.Collections.Generic.List<(int, string, int)>();
    int pos = 8;
    while (pos + 12 <= png.Length)
    {
      int len = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(pos));
      list.Add((pos, Encoding.ASCII.GetString(png, pos + 4, 4), len));
      pos += 12 + len;
    }
    return list.ToArray();
  }

  public static Rgb8Image RandomImage(int width, int height, int seed)
  {
    Rgb8Image image = new(width, height);
    new Random(seed).NextBytes(image.Data);
    return image;
  }

  /// <summary>Smooth gradients with noise: compresses like a render, unlike pure noise.</summary>
  public static Rgb8Image RenderLikeImage(int width, int height, int seed)
  {
    Random rnd = new(seed);
    Rgb8Image image = new(width, height);
    for (int y = 0; y < height; y++)
    {
      for (int x = 0; x < width; x++)
      {
        double dx = x - width * 0.5, dy = y - height * 0.5;
        bool sphere = dx * dx + dy * dy < height * height * 0.1;
        int baseR = sphere ? 200 - (int)(Math.Sqrt(dx * dx + dy * dy) / 2) : 40 + y / 8;
        int noise = rnd.Next(-2, 3);
        image.SetPixel(x, y, (byte)Math.Clamp(baseR + noise, 0, 255), (byte)Math.Clamp(baseR / 2 + noise, 0, 255), (byte)(sphere ? 30 : 90 + x / 16));
      }
    }
    return image;
  }
}
