using System;

namespace Rendering.Imaging;

/// <summary>
/// CRC-32 (ISO-HDLC, reflected polynomial 0xEDB88320) as PNG chunks use it.
/// Table-driven because System.IO.Hashing is not available offline.
/// </summary>
internal static class Crc32
{
  private static readonly uint[] Table = BuildTable();

  public static uint Compute(ReadOnlySpan<byte> data) => Finish(Update(Start, data));

  public const uint Start = 0xFFFFFFFFu;

  public static uint Update(uint crc, ReadOnlySpan<byte> data)
  {
    uint[] table = Table;
    foreach (byte b in data)
      crc = table[(crc ^ b) & 0xFF] ^ (crc >> 8);
    return crc;
  }

  public static uint Finish(uint crc) => crc ^ 0xFFFFFFFFu;

  private static uint[] BuildTable()
  {
    uint[] table = new uint[256];
    for (uint n = 0; n < 256; n++)
    {
      uint c = n;
      for (int k = 0; k < 8; k++)
        c = (c & 1) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[n] = c;
    }
    return table;
  }
}
