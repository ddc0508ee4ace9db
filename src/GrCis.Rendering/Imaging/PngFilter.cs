using System;

namespace Rendering.Imaging;

/// <summary>PNG scanline filters (spec section 9); all operate on whole bytes, bpp = bytes per complete pixel (min 1).</summary>
internal static class PngFilter
{
  public const byte None = 0, Sub = 1, Up = 2, Average = 3, Paeth = 4;

  /// <summary>Filters <paramref name="row"/> into <paramref name="dest"/>; <paramref name="prior"/> is all zeros for the first row.</summary>
  public static void Apply(byte type, ReadOnlySpan<byte> row, ReadOnlySpan<byte> prior, int bpp, Span<byte> dest)
  {
    int n = row.Length;
    switch (type)
    {
      case None:
        row.CopyTo(dest);
        break;
      case Sub:
        for (int i = 0; i < n; i++)
          dest[i] = (byte)(row[i] - (i >= bpp ? row[i - bpp] : 0));
        break;
      case Up:
        for (int i = 0; i < n; i++)
          dest[i] = (byte)(row[i] - prior[i]);
        break;
      case Average:
        for (int i = 0; i < n; i++)
          dest[i] = (byte)(row[i] - (((i >= bpp ? row[i - bpp] : 0) + prior[i]) >> 1));
        break;
      case Paeth:
        for (int i = 0; i < n; i++)
        {
          int a = i >= bpp ? row[i - bpp] : 0;
          int c = i >= bpp ? prior[i - bpp] : 0;
          dest[i] = (byte)(row[i] - Predict(a, prior[i], c));
        }
        break;
      default:
        throw new ArgumentOutOfRangeException(nameof(type), type, "PNG filter type must be 0..4.");
    }
  }

  /// <summary>Reverses a filter in place; returns false for an unknown filter type.</summary>
  public static bool Undo(byte type, Span<byte> row, ReadOnlySpan<byte> prior, int bpp)
  {
    int n = row.Length;
    switch (type)
    {
      case None:
        return true;
      case Sub:
        for (int i = bpp; i < n; i++)
          row[i] += row[i - bpp];
        return true;
      case Up:
        for (int i = 0; i < n; i++)
          row[i] += prior[i];
        return true;
      case Average:
        for (int i = 0; i < n; i++)
          row[i] += (byte)(((i >= bpp ? row[i - bpp] : 0) + prior[i]) >> 1);
        return true;
      case Paeth:
        for (int i = 0; i < n; i++)
        {
          int a = i >= bpp ? row[i - bpp] : 0;
          int c = i >= bpp ? prior[i - bpp] : 0;
          row[i] += (byte)Predict(a, prior[i], c);
        }
        return true;
      default:
        return false;
    }
  }

  /// <summary>Libpng's heuristic: bytes read as signed, smallest sum of magnitudes compresses best.</summary>
  public static long Cost(ReadOnlySpan<byte> filtered)
  {
    long sum = 0;
    foreach (byte b in filtered)
      sum += b < 128 ? b : 256 - b;
    return sum;
  }

  private static int Predict(int a, int b, int c)
  {
    int p = a + b - c;
    int pa = Math.Abs(p - a);
    int pb = Math.Abs(p - b);
    int pc = Math.Abs(p - c);
    if (pa <= pb && pa <= pc)
      return a;
    return pb <= pc ? b : c;
  }
}
