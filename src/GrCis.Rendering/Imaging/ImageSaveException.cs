using System;
using System.IO;

namespace Rendering.Imaging;

/// <summary>Saving an image file failed; the target file was left as it was and no temporary file remains.</summary>
public sealed class ImageSaveException : IOException
{
  /// <summary>The file that could not be written.</summary>
  public string Path { get; }

  /// <summary>Saving to <paramref name="path"/> failed because of <paramref name="innerException"/>; the message names both.</summary>
  /// <param name="path">The target file.</param>
  /// <param name="innerException">The reason.</param>
  public ImageSaveException(string path, Exception innerException)
    : base($"Could not save image to '{path}': {innerException.Message}", innerException)
  {
    Path = path;
  }
}
