using System;
using System.IO;
using System.Linq;
using System.Text;
using Rendering.Imaging;
using Rendering.Parts;

namespace Rendering.Tests.Parts;

/// <summary>A part's pixel data is checked: its CRC-32, and every value finite and of a sane size.</summary>
public sealed class PartFileTests : IDisposable
{
  readonly string _dir = Directory.CreateTempSubdirectory("grcis-partfile-").FullName;

  public void Dispose() => Directory.Delete(_dir, recursive: true);

  static readonly PartHeader Header = new()
  {
    Width = 40, Height = 36, Index = 1, Count = 2, SamplesPerPixel = 1, Seed = 1, Gamma = 2.2,
    Scene = "test", SettingsHash = new string('0', 64),
  };

  static FloatImage Image()
  {
    var image = new FloatImage(40, 36);
    for (int i = 0; i < image.Data.Length; i++)
      image.Data[i] = i % 7 / 7f;
    return image;
  }

  string Save(FloatImage image)
  {
    string path = Path.Combine(_dir, "p.grcis-part");
    PartFile.Save(path, Header, image);
    return path;
  }

  [Fact]
  public void Saved_part_reads_back_with_its_checksum()
  {
    string path = Save(Image());
    string text = Encoding.ASCII.GetString(File.ReadAllBytes(path).AsSpan(0, 400));
    Assert.StartsWith("grcis-part 2\n", text);
    Assert.Matches(@"\ncrc32 [0-9a-f]{8}\nend\n", text);
    (PartHeader h, float[] samples) = PartFile.Load(path);
    Assert.Equal(Header, h);
    var merged = new FloatImage(40, 36);
    PartFile.Place(h, samples, merged);
    Assert.Equal(Image().Data[(39 * 3)..(40 * 3)], merged.Data[(39 * 3)..(40 * 3)]);   // pixel (39, 0) is in part 1 (tile 1, 0)
  }

  [Theory]
  [InlineData(0)]
  [InlineData(17)]
  [InlineData(31)]
  public void Flipped_bit_in_the_pixel_data_is_refused_naming_the_file(int bit)
  {
    string path = Save(Image());
    byte[] bytes = File.ReadAllBytes(path);
    bytes[^(1 + bit * 13)] ^= (byte)(1 << (bit % 8));
    File.WriteAllBytes(path, bytes);
    string message = Assert.Throws<InvalidDataException>(() => PartFile.Load(path)).Message;
    Assert.StartsWith(path + ": pixel data damaged (CRC-32 ", message);
  }

  [Theory]
  [InlineData(float.NaN, "NaN")]
  [InlineData(float.PositiveInfinity, "Infinity")]
  [InlineData(float.NegativeInfinity, "-Infinity")]
  [InlineData(-1e30f, "-1E+30")]
  [InlineData(2e15f, "2E+15")]
  public void Non_finite_or_absurd_value_is_refused_naming_the_pixel(float value, string shown)
  {
    FloatImage image = Image();
    image.Data[image.PixelIndex(39, 0) + 1] = value;
    string path = Save(image);   // a valid checksum: the values themselves are wrong
    string message = Assert.Throws<InvalidDataException>(() => PartFile.Load(path)).Message;
    Assert.Equal($"{path}: pixel (39, 0) holds {shown}, not a colour value (NaN, infinite or beyond ±1e15)", message);
  }

  [Fact]
  public void Largest_sane_values_are_kept()
  {
    FloatImage image = Image();
    image.Data[image.PixelIndex(39, 0)] = PartFile.MaxMagnitude;
    image.Data[image.PixelIndex(39, 0) + 1] = -0.25f;
    (_, float[] samples) = PartFile.Load(Save(image));
    Assert.Contains(PartFile.MaxMagnitude, samples);
  }

  [Theory]
  [InlineData("grcis-part 1", "part file format 1 (an older grcis); this grcis reads format 2: render the part again")]
  [InlineData("grcis-part 3", "part file format 3 (a newer grcis); this grcis reads format 2")]
  [InlineData("grcis-parts", "not a grcis part file (expected 'grcis-part 2')")]
  public void Other_format_versions_are_refused_saying_which(string firstLine, string expected)
  {
    string path = Save(Image());
    byte[] bytes = File.ReadAllBytes(path);
    int eol = Array.IndexOf(bytes, (byte)'\n');
    File.WriteAllBytes(path, [.. Encoding.ASCII.GetBytes(firstLine), .. bytes.AsSpan(eol).ToArray()]);
    Assert.Equal($"{path}: {expected}", Assert.Throws<InvalidDataException>(() => PartFile.Load(path)).Message);
  }
}
