using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using Rendering.Execution;
using Rendering.Imaging;

namespace Rendering.Parts;

/// <summary>
/// A <c>.grcis-part</c> file: an ASCII header of <c>key value</c> lines ending with <c>end</c>, then the
/// part's tiles (in <see cref="PartLayout.Tiles"/> order, rows top to bottom inside a tile) as
/// little-endian float32 linear RGB. The header carries the CRC-32 of those bytes, so a part damaged on
/// the way (a flipped bit, a copy cut and padded) is refused instead of merged. docs/scale-out.md
/// describes every key.
/// </summary>
public static class PartFile
{
  /// <summary>Format 2 added the <c>crc32</c> line; format 1 files are refused with a message saying so.</summary>
  public const int Version = 2;
  /// <summary>The first header line of every part file (format name and version).</summary>
  public const string Magic = "grcis-part 2";
  const string MagicPrefix = "grcis-part ";

  /// <summary>
  /// Largest magnitude a stored sample may have: far above any radiance a render gives, far below float's
  /// range, so a value that is nonsense (a damaged or forged file) is refused rather than merged.
  /// </summary>
  public const float MaxMagnitude = 1e15f;
  /// <summary>File name extension of part files.</summary>
  public const string Extension = ".grcis-part";
  const int MaxHeaderBytes = 4096;

  /// <summary>Writes the tiles of <paramref name="header"/>'s part, taken from the full-size <paramref name="image"/>, atomically.</summary>
  /// <exception cref="ImageSaveException">The file could not be written; an existing target is unchanged.</exception>
  public static void Save(string path, PartHeader header, FloatImage image)
  {
    ArgumentNullException.ThrowIfNull(header);
    ArgumentNullException.ThrowIfNull(image);
    if (image.Width != header.Width || image.Height != header.Height || image.Bands != header.Bands)
      throw new ArgumentException($"Image {image.Width}x{image.Height}x{image.Bands} does not match the part header.", nameof(image));
    List<Tile> tiles = PartLayout.Tiles(header.Width, header.Height, header.Index, header.Count);
    // The data is laid out first: its checksum goes in the header that precedes it.
    byte[] data = new byte[PartLayout.SampleCount(tiles, header.Bands) * 4];
    int k = 0;
    foreach (Tile t in tiles)
      for (int y = t.Y1; y < t.Y2; y++)
        foreach (float v in image.Data.AsSpan(image.PixelIndex(t.X1, y), (t.X2 - t.X1) * header.Bands))
        {
          BinaryPrimitives.WriteSingleLittleEndian(data.AsSpan(k), v);
          k += 4;
        }
    AtomicFile.Write(path, s =>
    {
      s.Write(Encoding.UTF8.GetBytes(HeaderText(header, data.Length / 4, Crc32.Compute(data))));
      s.Write(data);
    });
  }

  /// <summary>Reads a part: its header and its samples, checked against the layout.</summary>
  /// <exception cref="InvalidDataException">Not a part file, or truncated; the message starts with the path.</exception>
  public static (PartHeader Header, float[] Samples) Load(string path) => FileDecoding.Load(path, Decode);


  /// <summary>Copies a part's samples into the full-size <paramref name="image"/>.</summary>
  public static void Place(PartHeader header, float[] samples, FloatImage image)
  {
    int k = 0;
    foreach (Tile t in PartLayout.Tiles(header.Width, header.Height, header.Index, header.Count))
      for (int y = t.Y1; y < t.Y2; y++)
      {
        int n = (t.X2 - t.X1) * header.Bands;
        samples.AsSpan(k, n).CopyTo(image.Data.AsSpan(image.PixelIndex(t.X1, y), n));
        k += n;
      }
  }

  static string HeaderText(PartHeader h, long samples, uint crc) => string.Create(CultureInfo.InvariantCulture, $"""
    {Magic}
    layout {h.Layout}
    size {h.Width}x{h.Height}
    bands {h.Bands}
    part {h.Index}/{h.Count}
    spp {h.SamplesPerPixel}
    seed {h.Seed}
    gamma {h.Gamma:R}
    scene {h.Scene}
    settings {h.SettingsHash}
    samples {samples}
    crc32 {crc:x8}
    end

    """);

  internal static (PartHeader Header, float[] Samples) Decode(byte[] bytes)
  {
    int end = IndexOfEnd(bytes);
    var fields = new Dictionary<string, string>(StringComparer.Ordinal);
    string[] lines = Encoding.UTF8.GetString(bytes, 0, end).TrimEnd('\n').Split('\n');
    foreach (string line in lines[1..])
    {
      int sp = line.IndexOf(' ');
      if (sp <= 0)
        throw new InvalidDataException($"malformed header line '{line}'");
      fields[line[..sp]] = line[(sp + 1)..];
    }

    string layout = Field(fields, "layout");
    if (layout != PartLayout.Name)
      throw new InvalidDataException($"unknown layout '{layout}' (this grcis reads {PartLayout.Name})");
    string[] size = Field(fields, "size").Split('x');
    string[] part = Field(fields, "part").Split('/');
    if (size.Length != 2 || part.Length != 2)
      throw new InvalidDataException("malformed size or part");
    var header = new PartHeader
    {
      Width = Int(size[0], "size"),
      Height = Int(size[1], "size"),
      Bands = Int(Field(fields, "bands"), "bands"),
      Index = Int(part[0], "part"),
      Count = Int(part[1], "part"),
      SamplesPerPixel = Int(Field(fields, "spp"), "spp"),
      Seed = long.TryParse(Field(fields, "seed"), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long seed) ? seed : throw Bad("seed"),
      Gamma = double.TryParse(Field(fields, "gamma"), NumberStyles.Float, CultureInfo.InvariantCulture, out double g) && g > 0 ? g : throw Bad("gamma"),
      Scene = Field(fields, "scene"),
      SettingsHash = Field(fields, "settings"),
      Layout = layout,
    };
    if (header.Width < 1 || header.Height < 1 || header.Bands != 3 || header.Count < 1 || header.Index >= header.Count ||
        (long)header.Width * header.Height * header.Bands > FloatImage.MaxSamples)
      throw new InvalidDataException("size, bands or part out of range");

    long expected = PartLayout.SampleCount(PartLayout.Tiles(header.Width, header.Height, header.Index, header.Count), header.Bands);
    if (Int(Field(fields, "samples"), "samples") != expected)
      throw new InvalidDataException($"header says {fields["samples"]} samples, part {header.Index}/{header.Count} of {header.Width}x{header.Height} holds {expected}");
    int dataStart = end + "end\n".Length;
    if (bytes.Length - dataStart != expected * 4)
      throw new InvalidDataException($"pixel data truncated or padded: {bytes.Length - dataStart} bytes, expected {expected * 4}");
    ReadOnlySpan<byte> data = bytes.AsSpan(dataStart);
    if (!uint.TryParse(Field(fields, "crc32"), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint crc))
      throw Bad("crc32");
    if (Crc32.Compute(data) != crc)
      throw new InvalidDataException($"pixel data damaged (CRC-32 {Crc32.Compute(data):x8}, header says {crc:x8})");
    float[] samples = new float[expected];
    for (int i = 0; i < samples.Length; i++)
      samples[i] = BinaryPrimitives.ReadSingleLittleEndian(data[(4 * i)..]);
    CheckValues(header, samples);
    return (header, samples);
  }

  /// <summary>Refuses NaN, infinities and magnitudes above <see cref="MaxMagnitude"/>, naming the first such pixel.</summary>
  static void CheckValues(PartHeader header, float[] samples)
  {
    int k = 0;
    foreach (Tile t in PartLayout.Tiles(header.Width, header.Height, header.Index, header.Count))
      for (int y = t.Y1; y < t.Y2; y++)
        for (int x = t.X1; x < t.X2; x++)
          for (int b = 0; b < header.Bands; b++, k++)
          {
            float v = samples[k];
            if (!float.IsFinite(v) || Math.Abs(v) > MaxMagnitude)
              throw new InvalidDataException(string.Create(CultureInfo.InvariantCulture,
                $"pixel ({x}, {y}) holds {v:R}, not a colour value (NaN, infinite or beyond ±{MaxMagnitude:0e0})"));
          }
  }

  /// <summary>Offset of the "end\n" line that closes the header.</summary>
  static int IndexOfEnd(byte[] bytes)
  {
    ReadOnlySpan<byte> head = bytes.AsSpan(0, Math.Min(bytes.Length, MaxHeaderBytes));
    if (!head.StartsWith(Encoding.ASCII.GetBytes(Magic + "\n")))
    {
      int eol = head.IndexOf((byte)'\n');
      if (head.StartsWith(Encoding.ASCII.GetBytes(MagicPrefix)) && eol > 0 &&
          int.TryParse(head[MagicPrefix.Length..eol], NumberStyles.None, CultureInfo.InvariantCulture, out int version))
        throw new InvalidDataException(version < Version
          ? $"part file format {version} (an older grcis); this grcis reads format {Version}: render the part again"
          : $"part file format {version} (a newer grcis); this grcis reads format {Version}");
      throw new InvalidDataException($"not a grcis part file (expected '{Magic}')");
    }
    int i = head.IndexOf("\nend\n"u8);
    if (i < 0)
      throw new InvalidDataException("header truncated (no 'end' line)");
    return i + 1;
  }

  static string Field(Dictionary<string, string> fields, string key) =>
    fields.TryGetValue(key, out string? v) ? v : throw new InvalidDataException($"header has no '{key}'");

  static int Int(string s, string what) =>
    int.TryParse(s, NumberStyles.None, CultureInfo.InvariantCulture, out int v) ? v : throw Bad(what);

  static InvalidDataException Bad(string what) => new($"malformed '{what}' in header");
}
