using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Text;
using OpenTK.Mathematics;
using Rendering.Imaging;
using Rendering.Parts;
using Scene3D;
using StbImageWriteSharp;

namespace Rendering.Tests.Robustness;

/// <summary>
/// Damaged files (truncations, bit flips, overwritten bytes, random tails, random bytes) of small valid
/// images, OBJ meshes and part files: every reader ends each case quickly with a result or its own
/// exception type, never a hang, a crash or another exception.
/// </summary>
public sealed class ReaderFuzzTests : IDisposable
{
  readonly string _dir = Directory.CreateTempSubdirectory("grcis-fuzz-").FullName;

  public void Dispose() => Directory.Delete(_dir, recursive: true);

  static Rgb8Image Pattern(int w, int h)
  {
    var image = new Rgb8Image(w, h);
    for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++)
        image.SetPixel(x, y, (byte)(x * 255 / w), (byte)(y * 255 / h), (byte)((x ^ y) * 16));
    return image;
  }

  static byte[] Stb(Action<ImageWriter, Stream> write)
  {
    using var ms = new MemoryStream();
    write(new ImageWriter(), ms);
    return ms.ToArray();
  }

  /// <summary>A 16x3 Radiance file, flat RGBE or with run-length scanlines (each channel one literal run).</summary>
  static byte[] Hdr(bool runLength)
  {
    const int w = 16, h = 3;
    var bytes = new List<byte>(Encoding.ASCII.GetBytes($"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {h} +X {w}\n"));
    for (int y = 0; y < h; y++)
    {
      byte[][] rgbe = [.. Enumerable.Range(0, 4).Select(c => Enumerable.Range(0, w).Select(x => (byte)(c == 3 ? 128 + y : 16 * c + x)).ToArray())];
      if (runLength)
      {
        bytes.AddRange([2, 2, 0, w]);
        foreach (byte[] channel in rgbe)
        {
          bytes.Add(w);
          bytes.AddRange(channel);
        }
      }
      else
        for (int x = 0; x < w; x++)
          bytes.AddRange([rgbe[0][x], rgbe[1][x], rgbe[2][x], rgbe[3][x]]);
    }
    return [.. bytes];
  }

  /// <summary>Small valid files of every format the image reader takes.</summary>
  static IEnumerable<(string Name, byte[] Bytes)> Images()
  {
    Rgb8Image p = Pattern(16, 12);
    yield return ("png", PngEncoder.Default.Encode(p));
    yield return ("jpeg", Stb((w, s) => w.WriteJpg(p.Data, p.Width, p.Height, ColorComponents.RedGreenBlue, s, 90)));
    yield return ("bmp", Stb((w, s) => w.WriteBmp(Pattern(7, 5).Data, 7, 5, ColorComponents.RedGreenBlue, s)));
    yield return ("tga", Stb((w, s) => w.WriteTga(p.Data, p.Width, p.Height, ColorComponents.RedGreenBlue, s)));
    yield return ("hdr", Hdr(runLength: false));
    yield return ("run-length hdr", Hdr(runLength: true));
    yield return ("pfm", PfmWriter.Encode(new FloatImage(4, 3, 3, Enumerable.Range(0, 36).Select(i => (float)i).ToArray())));
    // The smallest GIF (1x1), and the JFIF start that once spun for ever.
    yield return ("gif", Convert.FromHexString("4749463839610100010080000000FFFFFF00000021F90401000000002C00000000010001000002024401003B"));
    yield return ("jfif header", Convert.FromHexString("FFD8FFE000104A46494600"));
  }

  static bool IsImageError(Exception e) => e is InvalidDataException && !e.Message.Contains('\n');

  [Fact]
  public void Image_reader_ends_every_damaged_file_with_an_image_or_InvalidDataException()
  {
    int seed = 1;
    int n = Images().Sum(f => BoundedCases.Run(FuzzCases.Of(f.Name, f.Bytes, seed++), b => ImageFile.Decode(b), IsImageError));
    Assert.True(n > 4000, $"{n} cases");
  }

  [Theory]
  [InlineData("FFD8FFE00010")]
  [InlineData("FFD8FFE000104A46494600")]
  [InlineData("FFD8FFE000104A4649460001010000010001000055AA55AA")]
  public void Cut_JPEG_is_one_error_naming_the_file(string hex)
  {
    string path = Path.Combine(_dir, "t.jpg");
    File.WriteAllBytes(path, Convert.FromHexString(hex));
    BoundedCases.Run([("t.jpg", [])], _ =>
    {
      var e = Assert.Throws<InvalidDataException>(() => ImageFile.Load(path));
      Assert.StartsWith(path + ": corrupt or unsupported image (", e.Message);
      Assert.Throws<InvalidDataException>(() => ImageFile.LoadRgb8(path));
    }, _ => false);
  }

  [Fact]
  public void Declared_size_beyond_the_pixel_limit_is_refused_before_decoding()
  {
    // A PNG header saying 16384x16385 (within what the decoder itself allows, 2^28 + 16384 pixels) and four pixels of data.
    byte[] png = PngEncoder.Default.Encode(Pattern(2, 2));
    png[16] = png[17] = png[20] = png[21] = 0;
    (png[18], png[19], png[22], png[23]) = (0x40, 0x00, 0x40, 0x01);
    var e = Assert.Throws<InvalidDataException>(() => ImageFile.Decode(png));
    Assert.Equal("corrupt or unsupported image (declared size 16384x16385 is out of range)", e.Message);
  }

  const string Obj = """
    # a corner of a cube
    v 0 0 0
    v 1 0 0
    v 0 1 0
    v 0 0 1.5e0
    vt 0 0
    vt 1 0
    vt 0 1
    vn 0 0 1
    g corner
    usemtl red
    f 1/1/1 2/2/1 3/3/1
    f 1//1 3//1 4//1
    f -4 -3 -1
    f 2/2 3/3 4/1
    """;

  static bool IsMeshError(Exception e) => e is MeshFormatException && !e.Message.Contains('\n');

  [Fact]
  public void Obj_reader_ends_every_damaged_file_with_a_mesh_or_MeshFormatException()
  {
    byte[] text = Encoding.UTF8.GetBytes(Obj.Replace("\r\n", "\n"));
    int n = BoundedCases.Run(FuzzCases.Of("obj", text, 11, flips: 800, bursts: 400), b =>
      new WavefrontObj().ReadBrep(new StreamReader(new MemoryStream(b)), new SceneBrep(), Matrix4d.Identity, "fuzz.obj"), IsMeshError);

    // The gzip path reads files: fewer cases, each written out.
    using var gz = new MemoryStream();
    using (var z = new GZipStream(gz, CompressionLevel.Optimal, leaveOpen: true))
      z.Write(text);
    string path = Path.Combine(_dir, "fuzz.obj.gz");
    n += BoundedCases.Run(FuzzCases.Of("obj.gz", gz.ToArray(), 12, flips: 150, bursts: 60, tails: 30, randoms: 20), b =>
    {
      File.WriteAllBytes(path, b);
      new WavefrontObj().ReadBrep(path, new SceneBrep());
    }, IsMeshError);
    Assert.True(n > 1500, $"{n} cases");
  }

  [Fact]
  public void Part_reader_ends_every_damaged_file_with_a_part_or_InvalidDataException()
  {
    var header = new PartHeader
    {
      Width = 70, Height = 40, Index = 1, Count = 3, SamplesPerPixel = 4, Seed = 7, Gamma = 2.2,
      Scene = "FiveBalls", SettingsHash = new string('a', 64),
    };
    var image = new FloatImage(70, 40);
    for (int i = 0; i < image.Data.Length; i++)
      image.Data[i] = i % 97 / 96f;
    string path = Path.Combine(_dir, "p.grcis-part");
    PartFile.Save(path, header, image);
    int n = BoundedCases.Run(FuzzCases.Of("part", File.ReadAllBytes(path), 21, flips: 600, bursts: 300), b => PartFile.Decode(b),
      e => e is InvalidDataException && !e.Message.Contains('\n'));
    Assert.True(n > 1500, $"{n} cases");
  }
}
