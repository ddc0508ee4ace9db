using System;
using System.IO;

namespace Rendering.Imaging;

/// <summary>Reads a whole file and decodes it; a decoding failure becomes one message <c>path: reason</c>.</summary>
internal static class FileDecoding
{
  public static T Load<T>(string path, Func<byte[], T> decode)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    path = Utilities.DataFiles.Resolve(path);
    byte[] bytes = File.ReadAllBytes(path);
    try
    {
      return decode(bytes);
    }
    catch (InvalidDataException ex)
    {
      throw new InvalidDataException($"{path}: {ex.Message}", ex);
    }
  }
}
