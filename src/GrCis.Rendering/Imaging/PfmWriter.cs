using System;
using System.Buffers.Binary;
using System.Globalization;
using System.IO;
using System.Text;

namespace Rendering.Imaging;

/// <summary>
/// Writes the linear framebuffer as a Portable Float Map: "PF" (3 bands) or "Pf" (1 band) header,
/// scale -1.0 meaning little-endian, float32 samples, rows bottom to top as the format requires.
/// </summary>
public static class PfmWriter
{
  /// <summary>Writes <paramref name="image"/> (1 or 3 bands) to <paramref name="output"/> as a PFM file.</summary>
  /// <exception cref="ArgumentNullException">An argument is null.</exception>
  /// <exception cref="ArgumentException">The image has neither 1 nor 3 bands.</exception>
  public static void Write(FloatImage image, Stream output)
  {
    ArgumentNullException.ThrowIfNull(image);
    ArgumentNullException.ThrowIfNull(output);
    string magic = image.Bands switch
    {
      3 => "PF",
      1 => "Pf",
      _ => throw new ArgumentException($"PFM stores 1 or 3 bands; this image has {image.Bands}.", nameof(image)),
    };
    // Invariant culture: a comma decimal separator would make the scale unreadable.
    string header = string.Create(CultureInfo.InvariantCulture, $"{magic}\n{image.Width} {image.Height}\n-1.0\n");
    output.Write(Encoding.ASCII.GetBytes(header));

    int rowSamples = image.Width * image.Bands;
    byte[] row = new byte[rowSamples * 4];
    for (int y = image.Height - 1; y >= 0; y--)
    {
      ReadOnlySpan<float> src = image.Data.AsSpan(y * rowSamples, rowSamples);
      for (int i = 0; i < src.Length; i++)
        BinaryPrimitives.WriteSingleLittleEndian(row.AsSpan(4 * i), src[i]);
      output.Write(row);
    }
  }

  /// <summary>The bytes of the PFM file of <paramref name="image"/> (1 or 3 bands; see <see cref="Write"/>).</summary>
  public static byte[] Encode(FloatImage image)
  {
    using MemoryStream ms = new();
    Write(image, ms);
    return ms.ToArray();
  }

  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, FloatImage image)
  {
    ArgumentNullException.ThrowIfNull(image);
    if (image.Bands != 1 && image.Bands != 3)
      throw new ArgumentException($"PFM stores 1 or 3 bands; this image has {image.Bands}.", nameof(image));
    AtomicFile.Write(path, s => Write(image, s));
  }
}
