using System;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;

namespace Rendering.Imaging;

/// <summary>PNG scanline filters (spec section 9); all operate on whole bytes, bpp = bytes per complete pixel (min 1).</summary>
internal static class PngFilter
{
  public const byte None = 0, Sub = 1, Up = 2, Average = 3, Paeth = 4;

  /// <summary>Filters <paramref name="row"/> into <paramref name="dest"/>; <paramref name="prior"/> is all zeros for the first row.</summary>
  /// <remarks>
  /// Sixteen bytes at a time where the hardware allows: the same bytes as the per-byte definitions, which finish each
  /// row's tail. A render's save in a fresh process filters every row five times (adaptive choice), mostly before the
  /// JIT has optimised this code, so the vector steps count there most. Its vector code is not in the ReadyToRun image,
  /// so it is compiled optimized at its first call: a save in a fresh process otherwise runs it as tier-0 code.
  /// </remarks>
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]
  public static void Apply(byte type, ReadOnlySpan<byte> row, ReadOnlySpan<byte> prior, int bpp, Span<byte> dest)
  {
    int n = row.Length;
    if (prior.Length < n || dest.Length < n || bpp < 1)
      throw new ArgumentException("The prior row and the destination must be as long as the row, and bpp at least 1.");
    int head = Math.Min(bpp, n);   // bytes with no left neighbour (it counts as 0)
    int i;
    switch (type)
    {
      case None:
        row.CopyTo(dest);
        break;
      case Sub:
        row[..head].CopyTo(dest);
        i = head;
        if (Vector128.IsHardwareAccelerated)
          for (; i + 16 <= n; i += 16)
            (Vector128.Create(row.Slice(i, 16)) - Vector128.Create(row.Slice(i - bpp, 16))).CopyTo(dest.Slice(i, 16));
        for (; i < n; i++)
          dest[i] = (byte)(row[i] - row[i - bpp]);
        break;
      case Up:
        i = 0;
        if (Vector128.IsHardwareAccelerated)
          for (; i + 16 <= n; i += 16)
            (Vector128.Create(row.Slice(i, 16)) - Vector128.Create(prior.Slice(i, 16))).CopyTo(dest.Slice(i, 16));
        for (; i < n; i++)
          dest[i] = (byte)(row[i] - prior[i]);
        break;
      case Average:
        for (i = 0; i < head; i++)
          dest[i] = (byte)(row[i] - (prior[i] >> 1));
        if (Vector128.IsHardwareAccelerated)
          for (; i + 16 <= n; i += 16)
          {
            Vector128<byte> a = Vector128.Create(row.Slice(i - bpp, 16)), b = Vector128.Create(prior.Slice(i, 16));
            // ⌊(a + b) / 2⌋ without leaving bytes.
            Vector128<byte> mean = (a & b) + Vector128.ShiftRightLogical(a ^ b, 1);
            (Vector128.Create(row.Slice(i, 16)) - mean).CopyTo(dest.Slice(i, 16));
          }
        for (; i < n; i++)
          dest[i] = (byte)(row[i] - ((row[i - bpp] + prior[i]) >> 1));
        break;
      case Paeth:
        for (i = 0; i < head; i++)
          dest[i] = (byte)(row[i] - prior[i]);   // a = c = 0: the predictor is b
        if (Vector128.IsHardwareAccelerated)
          for (; i + 16 <= n; i += 16)
          {
            Vector128<byte> x = Vector128.Create(row.Slice(i, 16));
            Vector128<byte> a = Vector128.Create(row.Slice(i - bpp, 16)), b = Vector128.Create(prior.Slice(i, 16));
            Vector128<byte> c = Vector128.Create(prior.Slice(i - bpp, 16));
            var (aLo, aHi) = Vector128.Widen(a);
            var (bLo, bHi) = Vector128.Widen(b);
            var (cLo, cHi) = Vector128.Widen(c);
            Vector128<byte> predicted = Vector128.Narrow(Predict(aLo.AsInt16(), bLo.AsInt16(), cLo.AsInt16()).AsUInt16(),
                                                         Predict(aHi.AsInt16(), bHi.AsInt16(), cHi.AsInt16()).AsUInt16());
            (x - predicted).CopyTo(dest.Slice(i, 16));
          }
        for (; i < n; i++)
          dest[i] = (byte)(row[i] - Predict(row[i - bpp], prior[i], prior[i - bpp]));
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
  [MethodImpl(MethodImplOptions.AggressiveOptimization)]   // as Apply: optimized from a fresh process's first save
  public static long Cost(ReadOnlySpan<byte> filtered)
  {
    long sum = 0;
    int i = 0, n = filtered.Length;
    if (Vector128.IsHardwareAccelerated)
      while (i + 16 <= n)
      {
        // Eight 16-bit lanes take two magnitudes (≤ 128 each) per step: 255 steps stay below 65,536.
        Vector128<ushort> lanes = Vector128<ushort>.Zero;
        for (int steps = 0; steps < 255 && i + 16 <= n; steps++, i += 16)
        {
          // |−128| is −128 as a signed byte, 128 read unsigned: the magnitude wanted.
          var (lo, hi) = Vector128.Widen(Vector128.Abs(Vector128.Create(filtered.Slice(i, 16)).AsSByte()).AsByte());
          lanes += lo + hi;
        }
        var (l0, l1) = Vector128.Widen(lanes);
        sum += Vector128.Sum(l0 + l1);
      }
    for (; i < n; i++)
    {
      byte b = filtered[i];
      sum += b < 128 ? b : 256 - b;
    }
    return sum;
  }

  /// <summary>The Paeth predictor of eight pixels' bytes at once (16-bit lanes, values 0–255): the same choice as the scalar one.</summary>
  private static Vector128<short> Predict(Vector128<short> a, Vector128<short> b, Vector128<short> c)
  {
    // p = a + b − c, so |p − a| = |b − c|, |p − b| = |a − c|, |p − c| = |a + b − 2c|.
    Vector128<short> pa = Vector128.Abs(b - c), pb = Vector128.Abs(a - c), pc = Vector128.Abs(a + b - c - c);
    Vector128<short> takeA = Vector128.LessThanOrEqual(pa, pb) & Vector128.LessThanOrEqual(pa, pc);
    Vector128<short> takeB = Vector128.LessThanOrEqual(pb, pc);
    return Vector128.ConditionalSelect(takeA, a, Vector128.ConditionalSelect(takeB, b, c));
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
