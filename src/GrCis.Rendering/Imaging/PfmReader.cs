using System;
using System.Buffers.Binary;
using System.Globalization;
using System.IO;

namespace Rendering.Imaging;

/// <summary>
/// Reads a Portable Float Map: "PF" (3 bands) or "Pf" (1 band), width, height and scale in ASCII,
/// one whitespace byte, then float32 samples with rows bottom to top. A negative scale means
/// little-endian samples, a positive one big-endian; its magnitude is ignored (samples are returned as stored).
/// </summary>
public static class PfmReader
{
  /// <exception cref="InvalidDataException">Not a PFM file, or truncated.</exception>
  public static FloatImage Decode(ReadOnlySpan<byte> file)
  {
    int pos = 0;
    string magic = Token(file, ref pos, "magic");
    int bands = magic switch
    {
      "PF" => 3,
      "Pf" => 1,
      _ => throw new InvalidDataException("not a PFM file (expected 'PF' or 'Pf')"),
    };
    int width = Dimension(Token(file, ref pos, "width"), "width");
    int height = Dimension(Token(file, ref pos, "height"), "height");
    if (!double.TryParse(Token(file, ref pos, "scale"), NumberStyles.Float, CultureInfo.InvariantCulture, out double scale) ||
        scale == 0.0 || !double.IsFinite(scale))
      throw new InvalidDataException("PFM scale must be a non-zero number");
    pos++;   // the single whitespace byte that ends the header
    if ((long)width * height * bands > FloatImage.MaxSamples)
      throw new InvalidDataException($"PFM image {width}x{height} is too large");

    int rowSamples = width * bands;
    long needed = (long)rowSamples * height * 4;
    // Checked before allocating: a damaged size must not cost gigabytes.
    if (file.Length - pos < needed)
      throw new InvalidDataException($"PFM data truncated: {width}x{height}x{bands} needs {needed} bytes, {Math.Max(0, file.Length - pos)} present");
    var image = new FloatImage(width, height, bands);
    bool little = scale < 0.0;
    for (int row = 0; row < height; row++)
    {
      Span<float> dst = image.Data.AsSpan((height - 1 - row) * rowSamples, rowSamples);
      ReadOnlySpan<byte> src = file.Slice(pos + row * rowSamples * 4, rowSamples * 4);
      for (int i = 0; i < rowSamples; i++)
        dst[i] = little ? BinaryPrimitives.ReadSingleLittleEndian(src[(4 * i)..]) : BinaryPrimitives.ReadSingleBigEndian(src[(4 * i)..]);
    }
    return image;
  }

  /// <exception cref="InvalidDataException">Not a PFM file, or truncated; the message starts with the path.</exception>
  public static FloatImage Load(string path) => FileDecoding.Load(path, b => Decode(b));


  static string Token(ReadOnlySpan<byte> file, ref int pos, string what)
  {
    while (pos < file.Length && IsSpace(file[pos]))
      pos++;
    int start = pos;
    while (pos < file.Length && !IsSpace(file[pos]) && pos - start < 32)
      pos++;
    if (pos == start || pos >= file.Length)
      throw new InvalidDataException($"PFM header truncated before the {what}");
    return System.Text.Encoding.ASCII.GetString(file[start..pos]);
  }

  static int Dimension(string token, string what) =>
    int.TryParse(token, NumberStyles.None, CultureInfo.InvariantCulture, out int v) && v > 0
      ? v : throw new InvalidDataException($"PFM {what} '{token}' is not a positive integer");

  static bool IsSpace(byte b) => b is (byte)' ' or (byte)'\n' or (byte)'\r' or (byte)'\t';
}
