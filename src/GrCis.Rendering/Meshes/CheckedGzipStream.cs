using System;
using System.IO;
using System.IO.Compression;

namespace Rendering;

/// <summary>
/// Decompresses a gzip file and, at its end, checks the length against the gzip trailer: .NET's
/// <see cref="GZipStream"/> ends a truncated file silently, which would load half a mesh without a word.
/// Corrupt data surfaces as <see cref="InvalidDataException"/>.
/// </summary>
internal sealed class CheckedGzipStream : Stream
{
  readonly Stream file;
  readonly GZipStream gzip;
  readonly uint expectedLength;   // ISIZE: the uncompressed length modulo 2^32
  long length;

  public CheckedGzipStream(Stream file)
  {
    this.file = file;
    if (file.Length < 18)
      throw new InvalidDataException("the file is too short to be gzip data");
    Span<byte> trailer = stackalloc byte[4];
    file.Seek(-4, SeekOrigin.End);
    file.ReadExactly(trailer);
    expectedLength = BitConverter.ToUInt32(trailer);   // little endian, as gzip stores it
    if (!BitConverter.IsLittleEndian)
      expectedLength = System.Buffers.Binary.BinaryPrimitives.ReverseEndianness(expectedLength);
    file.Seek(0, SeekOrigin.Begin);
    gzip = new GZipStream(file, CompressionMode.Decompress);
  }

  public override int Read(byte[] buffer, int offset, int count) => Read(buffer.AsSpan(offset, count));

  public override int Read(Span<byte> buffer)
  {
    int n = gzip.Read(buffer);
    length += n;
    if (n == 0 && buffer.Length > 0 && (uint)length != expectedLength)
      throw new InvalidDataException("the gzip data ends early or its length does not match its trailer (truncated or corrupt file)");
    return n;
  }

  public override bool CanRead => true;
  public override bool CanSeek => false;
  public override bool CanWrite => false;
  public override long Length => throw new NotSupportedException();
  public override long Position { get => length; set => throw new NotSupportedException(); }
  public override void Flush() { }
  public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
  public override void SetLength(long value) => throw new NotSupportedException();
  public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

  protected override void Dispose(bool disposing)
  {
    if (disposing)
    {
      gzip.Dispose();
      file.Dispose();
    }
    base.Dispose(disposing);
  }
}
