using System;
using System.IO;
using System.Security.Cryptography;
using Rendering.Imaging;

namespace Rendering.Tests.Imaging;

/// <summary>The GrCis reference renders (640x480 RGB, written by System.Drawing, filters 1-4, many IDATs).</summary>
public class ReferenceImageTests
{
  // SHA-256 of the decoded RGB bytes, computed with an independent Python zlib + unfilter decoder.
  public static TheoryData<string, string> References => new()
  {
    { "Cylinders_640x480_ss1.png", "567fca43aec4ef05d650f944be4152b0af8bc40757bb2e33b86e5dd24766ac68" },
    { "FiveBalls_640x480_ss1.png", "cd1ebda80fb616f2b7e392fac70549c58be11ed0df739554a755b2f263a2be95" },
    { "SpherePlane_640x480_ss1.png", "c704a4b8f620350153eb4c7b0eac025a9feaf9b97546781193a4a27f570b3ad8" },
    { "Toroids_640x480_ss1.png", "59cf682b4c847e8e93f24c59f3b6672ff2392db5bfacefc4e51d4159b8f642c3" },
    { "TwoSpheres_640x480_ss1.png", "98de8a0975958d96ddaa8ad573ed02824097d1d1336204a3479233557a08b73c" },
  };

  [Theory]
  [MemberData(nameof(References))]
  public void DecodesReferenceAndReencodesIdentically(string name, string sha256)
  {
    string path = Path.Combine(RefsDirectory(), name);
    Rgb8Image image = PngFile.Load(path);
    Assert.Equal(640, image.Width);
    Assert.Equal(480, image.Height);
    Assert.Equal(sha256, Convert.ToHexStringLower(SHA256.HashData(image.Data)));

    Rgb8Image again = TestDecode.Png(PngEncoder.Default.Encode(image));
    Assert.True(image.ContentEquals(again));
    Assert.Equal(double.PositiveInfinity, ImageComparison.Psnr(image, again));
  }

  /// <summary>The reference renders in the shared folder.</summary>
  private static string RefsDirectory() => GrCis.Rendering.Tests.SharedFolder.Combine("refs", "grcis");
}
