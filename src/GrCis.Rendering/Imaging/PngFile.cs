using System;
using System.IO;

namespace Rendering.Imaging;

/// <summary>PNG convenience I/O on file paths. Saving is atomic: temp file in the same directory, then rename.</summary>
public static class PngFile
{
  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, Rgb8Image image, PngEncoder? encoder = null)
  {
    ArgumentNullException.ThrowIfNull(image);
    PngEncoder e = encoder ?? PngEncoder.Default;
    AtomicFile.Write(path, s => e.Encode(image, s));
  }

  /// <summary>Quantizes a linear framebuffer (see <see cref="Rgb8Image.FromFloatImage"/>) and saves it.</summary>
  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, FloatImage image, double gamma = 1.0, PngEncoder? encoder = null) =>
    Save(path, Rgb8Image.FromFloatImage(image, gamma), encoder);

  /// <exception cref="InvalidDataException">The file is not a PNG this decoder supports.</exception>
  public static Rgb8Image Load(string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    byte[] bytes = File.ReadAllBytes(path);
    try
    {
      return PngDecoder.Decode(bytes);
    }
    catch (InvalidDataException ex)
    {
      throw new InvalidDataException($"{path}: {ex.Message}", ex);
    }
  }
}
