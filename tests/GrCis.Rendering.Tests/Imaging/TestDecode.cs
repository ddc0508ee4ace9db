using System;
using System.IO;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>Decodes PNG bytes in memory through the library's reader (StbImageSharp), bad data as InvalidDataException.</summary>
internal static class TestDecode
{
  public static Rgb8Image Png(byte[] bytes)
  {
    try
    {
      return ImageFile.DecodeRgb8(bytes);
    }
    catch (Exception ex) when (ex is not InvalidDataException)
    {
      throw new InvalidDataException(ex.Message, ex);
    }
  }

  public static Rgb8Image Png(ReadOnlySpan<byte> bytes) => Png(bytes.ToArray());

  public static Rgb8Image Png(Stream s)
  {
    using MemoryStream ms = new();
    s.CopyTo(ms);
    return Png(ms.ToArray());
  }
}
