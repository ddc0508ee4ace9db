using System;
using System.IO;

namespace Rendering.Imaging;

/// <summary>Saving an image file failed; the target file was left as it was and no temporary file remains.</summary>
public sealed class ImageSaveException : IOException
{
  public string Path { get; }

  public ImageSaveException(string path, Exception innerException)
    : base($"Could not save image to '{path}': {innerException.Message}", innerException)
  {
    Path = path;
  }
}
