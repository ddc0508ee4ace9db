using System;
using System.Collections.Generic;
using System.IO;
using Rendering.Imaging;

namespace Rendering;

/// <summary>
/// Images of <see cref="ImageTexture"/>s read from files, shared while any texture holds them: a scene that
/// puts one file on fifty objects decodes it once. Entries are weak (the cache never keeps an image alive,
/// which matters in the long-running studio) and keyed by the file's full path, size and write time, so an
/// edited file is read again.
/// </summary>
internal static class TextureImageCache
{
  readonly record struct Key(string Path, long Length, DateTime WriteTime, double Gamma);

  static readonly Dictionary<Key, WeakReference<FloatImage>> images = new();
  static readonly object gate = new();

  /// <summary>The image of the file <paramref name="path"/> (already resolved), loaded by <see cref="ImageFile.Load"/>.</summary>
  public static FloatImage Load(string path, double gamma)
  {
    var info = new FileInfo(path);
    if (!info.Exists)
      return ImageFile.Load(path, gamma); // its FileNotFoundException names the path
    var key = new Key(info.FullName, info.Length, info.LastWriteTimeUtc, gamma);
    lock (gate)
      if (images.TryGetValue(key, out WeakReference<FloatImage>? weak) && weak.TryGetTarget(out FloatImage? cached))
        return cached;

    // Decoded outside the lock: two threads asking at once may both decode; either result is right.
    FloatImage image = ImageFile.Load(path, gamma);
    lock (gate)
    {
      RemoveDead();
      images[key] = new WeakReference<FloatImage>(image);
    }
    return image;
  }

  static void RemoveDead()
  {
    List<Key>? dead = null;
    foreach (KeyValuePair<Key, WeakReference<FloatImage>> kv in images)
      if (!kv.Value.TryGetTarget(out _))
        (dead ??= new List<Key>()).Add(kv.Key);
    if (dead != null)
      foreach (Key k in dead)
        images.Remove(k);
  }
}
