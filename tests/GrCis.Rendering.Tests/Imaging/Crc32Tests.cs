using System;
using System.Text;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

public class Crc32Tests
{
  [Fact]
  public void StandardCheckValue()
  {
    Assert.Equal(0xCBF43926u, Crc32.Compute(Encoding.ASCII.GetBytes("123456789")));
  }

  [Fact]
  public void EmptyInputIsZero()
  {
    Assert.Equal(0u, Crc32.Compute([]));
  }

  [Fact]
  public void IendChunkCrcMatchesEveryPngFile()
  {
    Assert.Equal(0xAE426082u, Crc32.Compute(Encoding.ASCII.GetBytes("IEND")));
  }

  [Fact]
  public void IncrementalUpdateEqualsOneShot()
  {
    byte[] data = Encoding.ASCII.GetBytes("IDATsome image bytes");
    uint split = Crc32.Finish(Crc32.Update(Crc32.Update(Crc32.Start, data.AsSpan(0, 4)), data.AsSpan(4)));
    Assert.Equal(Crc32.Compute(data), split);
  }
}
