using System;
using System.Runtime.CompilerServices;

namespace Rendering.Imaging;

/// <summary>
/// How linear float pixels become 8-bit display bytes: v^(1/<see cref="Gamma"/>), clamped to [0, 1],
/// then <see cref="Quantization"/>. NaN and negative values become 0. Every PNG writer and preview goes
/// through one of these, so the rule is written once.
/// <para>
/// Rendered images use <see cref="ForRender"/>: GrCis's truncation, so today's images equal the original
/// program's byte for byte (and every recorded image hash holds). Data maps (depth, normals, differences)
/// use <see cref="LinearRound"/>: no gamma, nearest byte, the better rule where no old output must match.
/// </para>
/// </summary>
public readonly record struct DisplayEncoding
{
  /// <summary>Display gamma (1 = linear); positive and finite.</summary>
  public double Gamma { get; }

  /// <summary>How a [0, 1] value becomes a byte.</summary>
  public Quantization Quantization { get; }

  readonly double invGamma;

  /// <exception cref="ArgumentOutOfRangeException"><paramref name="gamma"/> is not a positive finite number.</exception>
  public DisplayEncoding(double gamma, Quantization quantization)
  {
    if (!(gamma > 0.0) || double.IsInfinity(gamma))
      throw new ArgumentOutOfRangeException(nameof(gamma), gamma, "Gamma must be a positive finite number.");
    if (quantization is not (Quantization.Round or Quantization.Truncate))
      throw new ArgumentOutOfRangeException(nameof(quantization), quantization, "Unknown quantization.");
    Gamma = gamma;
    Quantization = quantization;
    invGamma = 1.0 / gamma;
  }

  /// <summary>
  /// The encoding of a rendered image shown or saved by any front end: <paramref name="gamma"/> as the
  /// renderer's <c>Gamma</c> (≤ 0.001 means linear, as in GrCis's <c>ApplyGamma</c>) and truncation.
  /// </summary>
  public static DisplayEncoding ForRender(double gamma) =>
    new(!Execution.RenderDefaults.IsLinearGamma(gamma) && !double.IsInfinity(gamma) ? gamma : 1.0, Quantization.Truncate);

  /// <summary>No gamma, nearest byte: for data maps and other images that are not renders.</summary>
  public static DisplayEncoding LinearRound => new(1.0, Quantization.Round);

  /// <summary>One channel value to its display byte.</summary>
  public byte Encode(float v) => Encode((double)v);

  /// <summary>One channel value to its display byte.</summary>
  public byte Encode(double v)
  {
    // Written so NaN falls into the first branch.
    if (!(v > 0.0))
      return 0;
    if (v >= 1.0)
      return 255;
    double g = invGamma == 0.0 ? 1.0 : invGamma;   // default(DisplayEncoding) acts as linear
    if (g != 1.0)
      v = Math.Pow(v, g);
    return Quantization == Quantization.Truncate ? (byte)(int)(v * 255.0) : (byte)(int)(v * 255.0 + 0.5);
  }

  /// <summary>Encodes <paramref name="source"/> value by value into <paramref name="destination"/> (same length).</summary>
  /// <remarks>
  /// The bytes are those of <see cref="Encode(float)"/>, value by value; each encoding is a power, so this avoids most of
  /// them. An image's worth of values goes through a <see cref="StepTable"/> of the encoding; fewer values through a
  /// small direct-mapped memo of this call, which keeps the byte of the last value seen in each slot (renders repeat
  /// values: a background, flat colours).
  /// </remarks>
  [SkipLocalsInit]
  public void Encode(ReadOnlySpan<float> source, Span<byte> destination)
  {
    if (destination.Length != source.Length)
      throw new ArgumentException($"Destination has {destination.Length} bytes for {source.Length} values.", nameof(destination));
    if (source.Length >= StepTable.WorthFrom)
    {
      new StepTable(this).Encode(source, destination);
      return;
    }
    const int MemoBits = 10;
    Span<uint> keys = stackalloc uint[1 << MemoBits];
    Span<byte> bytes = stackalloc byte[1 << MemoBits];
    // Every slot starts as a true entry: a NaN's bits and its byte.
    uint empty = BitConverter.SingleToUInt32Bits(float.NaN);
    keys.Fill(empty);
    bytes.Fill(Encode(float.NaN));
    for (int i = 0; i < source.Length; i++)
    {
      float v = source[i];
      uint bits = BitConverter.SingleToUInt32Bits(v);
      int slot = (int)((bits * 0x9E3779B1u) >> (32 - MemoBits));
      if (keys[slot] != bits)
      {
        keys[slot] = bits;
        bytes[slot] = Encode(v);
      }
      destination[i] = bytes[slot];
    }
  }

  /// <summary>
  /// The bytes of an encoding for every float in [0, 1), from the float's top bits. The encoding never decreases as the
  /// value grows, and a positive float's bits order as its value, so it is a staircase: byte k from the first float whose
  /// byte is at least k, found for each k by bisection (about 7,700 powers). A bucket of 2^15 consecutive floats (sign,
  /// exponent and the first 8 mantissa bits alike) holds one byte, or one byte and, from a first float on, the next; the
  /// table keeps both. A bucket with two steps or more (only a gamma below 1 makes them) is encoded value by value. So
  /// every byte equals <see cref="DisplayEncoding.Encode(float)"/>'s.
  /// </summary>
  sealed class StepTable
  {
    /// <summary>The values from which the table's powers cost less than the memo's.</summary>
    public const int WorthFrom = 1 << 16;

    const int Shift = 15;
    const uint One = 0x3F800000u;   // the bits of 1f: every float below it is in a bucket
    const uint Direct = 0;          // a bucket encoded value by value (no true step is at a bucket's first float)

    readonly DisplayEncoding encoding;
    readonly byte[] low = new byte[One >> Shift];
    readonly uint[] next = new uint[One >> Shift];   // bits of the first float with byte low + 1; uint.MaxValue: none

    public StepTable(DisplayEncoding encoding)
    {
      this.encoding = encoding;
      // steps[k]: the bits of the first float whose byte is at least k + 1 (at most One, whose byte is 255).
      Span<uint> steps = stackalloc uint[255];
      uint from = 0;
      for (int k = 0; k < steps.Length; k++)
      {
        uint lo = from, hi = One;   // Byte(lo) <= k < Byte(hi), unless lo is 0 and its byte already more
        if (Byte(lo) > k)
        {
          steps[k] = lo;
          continue;
        }
        while (hi - lo > 1)
        {
          uint mid = lo + (hi - lo) / 2;
          if (Byte(mid) > k)
            hi = mid;
          else
            lo = mid;
        }
        steps[k] = from = hi;
      }
      int passed = 0;   // steps at or before the bucket's first float: its first byte
      for (uint b = 0; b < low.Length; b++)
      {
        uint first = b << Shift, end = first + (1u << Shift);
        while (passed < steps.Length && steps[passed] <= first)
          passed++;
        low[b] = (byte)passed;
        int inside = 0;
        while (passed + inside < steps.Length && steps[passed + inside] < end)
          inside++;
        next[b] = inside switch { 0 => uint.MaxValue, 1 => steps[passed], _ => Direct };
      }
    }

    byte Byte(uint bits) => encoding.Encode(BitConverter.UInt32BitsToSingle(bits));

    public void Encode(ReadOnlySpan<float> source, Span<byte> destination)
    {
      for (int i = 0; i < source.Length; i++)
      {
        uint bits = BitConverter.SingleToUInt32Bits(source[i]);
        if (bits < One)
        {
          uint b = bits >> Shift, step = next[b];
          if (step != Direct)
          {
            destination[i] = (byte)(low[b] + (bits >= step ? 1 : 0));
            continue;
          }
        }
        // Negative, NaN, 1 or more, or a bucket of several bytes.
        destination[i] = encoding.Encode(source[i]);
      }
    }
  }

  /// <summary>A 1-band image becomes gray, a 3-band image RGB.</summary>
  /// <exception cref="ArgumentException">The image has neither 1 nor 3 bands.</exception>
  public Rgb8Image Encode(FloatImage image)
  {
    ArgumentNullException.ThrowIfNull(image);
    if (image.Bands != 1 && image.Bands != 3)
      throw new ArgumentException($"Only 1- or 3-band images convert to RGB; this one has {image.Bands} bands.", nameof(image));
    Rgb8Image result = new(image.Width, image.Height);
    float[] src = image.Data;
    byte[] dst = result.Data;
    if (image.Bands == 3)
      Encode(src, dst);
    else
      for (int i = 0; i < src.Length; i++)
        dst[3 * i] = dst[3 * i + 1] = dst[3 * i + 2] = Encode(src[i]);
    return result;
  }
}
