using System;
using System.IO;

namespace Rendering.Imaging;

/// <summary>
/// The read-only stream StbImageSharp decodes from, over a file held in memory. StbImageSharp skips a
/// segment with <c>Seek(n, Current)</c> and tests for the end with <c>Position == Length</c>; over a
/// <see cref="MemoryStream"/> a skip past the end (a segment length larger than what is left) leaves the
/// position beyond the length, the end test never holds again and the JPEG marker loop spins for ever.
/// Here a seek stays within the data (a negative skip goes to the end, as stb_image's C skip does), and the
/// decoder may ask for only <see cref="PastEndBudget"/> bytes beyond the end in all (stb_image reads zeros
/// there, and a loop that keeps reading zeros is bounded by this).
/// </summary>
internal sealed class BoundedDecodeStream(byte[] data) : Stream
{
  /// <summary>Zero bytes a decoder may read past the end: a slightly cut JPEG still decodes, as it did before.</summary>
  public const int PastEndBudget = 1 << 20;

  int position;
  long pastEnd;

  public override bool CanRead => true;
  public override bool CanSeek => true;
  public override bool CanWrite => false;
  public override long Length => data.Length;

  public override long Position
  {
    get => position;
    set => position = (int)Math.Clamp(value, 0, data.Length);
  }

  public override int Read(byte[] buffer, int offset, int count) => Read(buffer.AsSpan(offset, count));

  public override int Read(Span<byte> buffer)
  {
    int n = Math.Min(buffer.Length, data.Length - position);
    data.AsSpan(position, n).CopyTo(buffer);
    position += n;
    if (n < buffer.Length)
      PastEnd(buffer.Length - n);
    return n;
  }

  public override int ReadByte()
  {
    if (position < data.Length)
      return data[position++];
    PastEnd(1);
    return -1;
  }

  void PastEnd(int count)
  {
    pastEnd += count;
    if (pastEnd > PastEndBudget)
      throw new InvalidDataException("unexpected end of data");
  }

  public override long Seek(long offset, SeekOrigin origin)
  {
    long target = origin switch
    {
      SeekOrigin.Begin => offset,
      SeekOrigin.Current => offset < 0 ? data.Length : position + offset,
      _ => data.Length + offset,
    };
    Position = target;
    return position;
  }

  public override void Flush() { }
  public override void SetLength(long value) => throw new NotSupportedException();
  public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
}
