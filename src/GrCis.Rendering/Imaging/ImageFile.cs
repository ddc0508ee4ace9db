using System;
using System.IO;
using StbImageSharp;

namespace Rendering.Imaging;

/// <summary>
/// The one entry point for reading images (textures, references, comparisons). PFM is read by
/// <see cref="PfmReader"/>; PNG, JPEG, BMP, TGA, GIF, PSD and Radiance HDR by StbImageSharp.
/// Every failure to understand a file is an <see cref="InvalidDataException"/> whose message is
/// <c>path: reason</c>.
/// </summary>
public static class ImageFile
{
  /// <summary>
  /// Loads any supported file as a linear 3-band image. PFM and HDR values are returned as stored
  /// (already linear). 8-bit files become (byte / 255)^<paramref name="gamma"/>: gamma 1 (the default)
  /// gives the stored values unchanged, as GrCis's bitmap textures read them; 2.2 undoes the display
  /// gamma <c>grcis render</c> writes by default. Gray files are replicated to RGB; alpha is dropped.
  /// </summary>
  /// <exception cref="InvalidDataException">Corrupt or unsupported file.</exception>
  public static FloatImage Load(string path, double gamma = 1.0)
  {
    if (!(gamma > 0.0) || double.IsInfinity(gamma))
      throw new ArgumentOutOfRangeException(nameof(gamma), gamma, "Gamma must be a positive finite number.");
    return FileDecoding.Load(path, bytes => Decode(bytes, gamma));
  }

  /// <summary>Decodes a file held in memory, as <see cref="Load"/> does; bad data is an <see cref="InvalidDataException"/> without the path.</summary>
  internal static FloatImage Decode(byte[] bytes, double gamma = 1.0)
  {
    if (IsPfm(bytes))
      return ToRgb(PfmReader.Decode(bytes));
    if (IsHdr(bytes))
    {
      ImageResultFloat hdr = Stb(() =>
      {
        CheckSize(bytes);
        return ImageResultFloat.FromStream(new BoundedDecodeStream(bytes), ColorComponents.RedGreenBlue);
      });
      return new FloatImage(hdr.Width, hdr.Height, 3, hdr.Data);
    }
    return ToLinear(Stb(() => DecodeRgb8(bytes)), gamma);
  }

  /// <summary>Loads an 8-bit file (PNG, JPEG, BMP, TGA, …) as RGB bytes, unchanged.</summary>
  /// <exception cref="InvalidDataException">Corrupt or unsupported file, or a float format (PFM, HDR).</exception>
  public static Rgb8Image LoadRgb8(string path) => FileDecoding.Load(path, bytes => IsPfm(bytes) || IsHdr(bytes)
    ? throw new InvalidDataException("a floating-point image; load it with ImageFile.Load")
    : Stb(() => DecodeRgb8(bytes)));

  /// <summary>Decodes an 8-bit file held in memory; StbImageSharp's own exception on bad data.</summary>
  internal static Rgb8Image DecodeRgb8(byte[] bytes)
  {
    CheckSize(bytes);
    ImageResult r = ImageResult.FromStream(new BoundedDecodeStream(bytes), ColorComponents.RedGreenBlue);
    return new Rgb8Image(r.Width, r.Height, r.Data);
  }

  /// <summary>
  /// Refuses a header that declares more pixels than an image may hold, before the decoder allocates and
  /// decodes them: a damaged size field would otherwise cost gigabytes and minutes for a few bytes of data.
  /// </summary>
  static void CheckSize(byte[] bytes)
  {
    ImageInfo? info = ImageInfo.FromStream(new BoundedDecodeStream(bytes));
    if (info is { } i && (i.Width <= 0 || i.Height <= 0 || (long)i.Width * i.Height > Rgb8Image.MaxPixels))
      throw new InvalidDataException($"declared size {i.Width}x{i.Height} is out of range");
  }

  static T Stb<T>(Func<T> decode)
  {
    try
    {
      return decode();
    }
    catch (InvalidDataException ex)
    {
      // The size check and the bounded stream name the problem; say what kind of file it was.
      throw new InvalidDataException($"corrupt or unsupported image ({ex.Message})", ex);
    }
    catch (Exception ex) when (ex is not OutOfMemoryException)
    {
      // StbImageSharp reports bad data with a plain exception carrying its failure reason, or an index error.
      throw new InvalidDataException(
        ex.GetType() == typeof(Exception) || ex is InvalidOperationException ? $"corrupt or unsupported image ({Printable(ex.Message)})" : "corrupt or unsupported image", ex);
    }
  }

  /// <summary>The decoder's reason as one short printable line: for an unknown PNG chunk it is the chunk's raw type bytes.</summary>
  static string Printable(string reason)
  {
    var text = new System.Text.StringBuilder(reason.Length);
    foreach (char c in reason.Length > 60 ? reason[..60] : reason)
      text.Append(c is >= ' ' and <= '~' ? c : '?');
    return text.ToString();
  }

  static bool IsPfm(ReadOnlySpan<byte> b) => b.Length >= 3 && b[0] == 'P' && (b[1] == 'F' || b[1] == 'f') && b[2] is (byte)'\n' or (byte)'\r' or (byte)' ' or (byte)'\t';

  static bool IsHdr(ReadOnlySpan<byte> b) => b.StartsWith("#?"u8);

  static FloatImage ToRgb(FloatImage image)
  {
    if (image.Bands == 3)
      return image;
    var rgb = new FloatImage(image.Width, image.Height);
    for (int i = 0; i < image.Data.Length; i++)
      rgb.Data[3 * i] = rgb.Data[3 * i + 1] = rgb.Data[3 * i + 2] = image.Data[i];
    return rgb;
  }

  static FloatImage ToLinear(Rgb8Image image, double gamma)
  {
    // One table of 256 values: every byte maps the same way.
    Span<float> table = stackalloc float[256];
    for (int v = 0; v < 256; v++)
      table[v] = (float)(gamma == 1.0 ? v / 255.0 : Math.Pow(v / 255.0, gamma));
    var result = new FloatImage(image.Width, image.Height);
    for (int i = 0; i < image.Data.Length; i++)
      result.Data[i] = table[image.Data[i]];
    return result;
  }
}
