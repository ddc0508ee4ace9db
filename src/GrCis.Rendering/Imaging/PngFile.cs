using System;
using System.Collections.Generic;
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

  /// <summary>
  /// Saves <paramref name="image"/> with text entries (<see cref="PngEncoder.Encode(Rgb8Image, Stream, IEnumerable{KeyValuePair{string, string}})"/>),
  /// atomically; <see cref="CheckedPng"/> reads them back.
  /// </summary>
  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, Rgb8Image image, IReadOnlyList<KeyValuePair<string, string>> text)
  {
    ArgumentNullException.ThrowIfNull(image);
    ArgumentNullException.ThrowIfNull(text);
    AtomicFile.Write(path, s => PngEncoder.Default.Encode(image, s, text));
  }

  /// <summary>Quantizes a linear framebuffer (see <see cref="Rgb8Image.FromFloatImage"/>) and saves it.</summary>
  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, FloatImage image, double gamma = 1.0, PngEncoder? encoder = null) =>
    Save(path, Rgb8Image.FromFloatImage(image, gamma), encoder);

  /// <summary>Reads a PNG (or another 8-bit format, see <see cref="ImageFile.LoadRgb8"/>) as RGB bytes.</summary>
  /// <exception cref="InvalidDataException">Corrupt or unsupported file; the message starts with the path.</exception>
  public static Rgb8Image Load(string path) => ImageFile.LoadRgb8(path);
}
