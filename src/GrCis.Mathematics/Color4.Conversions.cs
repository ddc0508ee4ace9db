using System;

namespace OpenTK.Mathematics;

// The colour-space conversions of OpenTK 4's Color4. Hue-based spaces store the hue as a fraction of a turn (0..1)
// in X; the alpha rides along in W.
public partial struct Color4
{
  /// <summary>Linear RGB from sRGB-encoded channels (the piecewise sRGB curve; alpha unchanged).</summary>
  public static Color4 FromSrgb(Color4 srgb) => new(SrgbToLinear(srgb.R), SrgbToLinear(srgb.G), SrgbToLinear(srgb.B), srgb.A);
  /// <summary>sRGB-encoded channels from linear RGB.</summary>
  public static Color4 ToSrgb(Color4 rgb) => new(LinearToSrgb(rgb.R), LinearToSrgb(rgb.G), LinearToSrgb(rgb.B), rgb.A);

  static float SrgbToLinear(float c) => c <= 0.04045f ? c / 12.92f : MathF.Pow((c + 0.055f) / 1.055f, 2.4f);
  static float LinearToSrgb(float c) => c <= 0.0031308f ? 12.92f * c : 1.055f * MathF.Pow(c, 1f / 2.4f) - 0.055f;

  /// <summary>RGB from (hue 0..1, saturation, lightness, alpha).</summary>
  public static Color4 FromHsl(Vector4 hsl)
  {
    float chroma = (1f - MathF.Abs(2f * hsl.Z - 1f)) * hsl.Y;
    (float r, float g, float b) = Sector(hsl.X * 6f, chroma);
    float m = MathF.Max(hsl.Z - chroma / 2f, 0f);
    return new Color4(r + m, g + m, b + m, hsl.W);
  }

  /// <summary>(hue 0..1, saturation, lightness, alpha) of an RGB colour; a grey has hue and saturation 0.</summary>
  public static Vector4 ToHsl(Color4 rgb)
  {
    (float hue, float max, float min) = Hue(rgb);
    float lightness = (max + min) / 2f;
    float spread = 1f - MathF.Abs(2f * lightness - 1f);
    return new Vector4(hue, spread != 0 ? (max - min) / spread : 0f, lightness, rgb.A);
  }

  /// <summary>RGB from (hue 0..1, saturation, value, alpha).</summary>
  public static Color4 FromHsv(Vector4 hsv)
  {
    float chroma = hsv.Z * hsv.Y;
    (float r, float g, float b) = Sector(hsv.X * 6f, chroma);
    float m = hsv.Z - chroma;
    return new Color4(r + m, g + m, b + m, hsv.W);
  }

  /// <summary>(hue 0..1, saturation, value, alpha) of an RGB colour.</summary>
  public static Vector4 ToHsv(Color4 rgb)
  {
    (float hue, float max, float min) = Hue(rgb);
    return new Vector4(hue, max != 0f ? (max - min) / max : 0f, max, rgb.A);
  }

  /// <summary>RGB from (hue 0..1, chroma, luma 0.30 R + 0.59 G + 0.11 B, alpha).</summary>
  public static Color4 FromHcy(Vector4 hcy)
  {
    (float r, float g, float b) = Sector(hcy.X * 6f, hcy.Y);
    float m = hcy.Z - (0.30f * r + 0.59f * g + 0.11f * b);
    return new Color4(r + m, g + m, b + m, hcy.W);
  }

  /// <summary>(hue 0..1, chroma max − min, luma, alpha) of an RGB colour.</summary>
  public static Vector4 ToHcy(Color4 rgb)
  {
    (float hue, float max, float min) = Hue(rgb);
    return new Vector4(hue, max - min, 0.30f * rgb.R + 0.59f * rgb.G + 0.11f * rgb.B, rgb.A);
  }

  /// <summary>RGB from CIE 1931 XYZ (the CIE RGB primaries, as OpenTK).</summary>
  public static Color4 FromXyz(Vector4 xyz) => new(
    0.41847f * xyz.X - 0.15866f * xyz.Y - 0.082835f * xyz.Z,
    -0.091169f * xyz.X + 0.25243f * xyz.Y + 0.015708f * xyz.Z,
    0.0009209f * xyz.X - 0.0025498f * xyz.Y + 0.17860f * xyz.Z,
    xyz.W);

  /// <summary>CIE 1931 XYZ of a CIE RGB colour.</summary>
  public static Vector4 ToXyz(Color4 rgb) => new(
    (0.49f * rgb.R + 0.31f * rgb.G + 0.20f * rgb.B) / 0.17697f,
    (0.17697f * rgb.R + 0.81240f * rgb.G + 0.01063f * rgb.B) / 0.17697f,
    (0.01f * rgb.G + 0.99f * rgb.B) / 0.17697f,
    rgb.A);

  /// <summary>RGB from full-range (JPEG) YCbCr.</summary>
  public static Color4 FromYcbcr(Vector4 ycbcr) => new(
    ycbcr.X + 1.402f * ycbcr.Z,
    ycbcr.X - 0.344136f * ycbcr.Y - 0.714136f * ycbcr.Z,
    ycbcr.X + 1.772f * ycbcr.Y,
    ycbcr.W);

  /// <summary>Full-range (JPEG) YCbCr of an RGB colour.</summary>
  public static Vector4 ToYcbcr(Color4 rgb) => new(
    0.299f * rgb.R + 0.587f * rgb.G + 0.114f * rgb.B,
    -0.168736f * rgb.R - 0.331264f * rgb.G + 0.5f * rgb.B,
    0.5f * rgb.R - 0.418688f * rgb.G - 0.081312f * rgb.B,
    rgb.A);

  /// <summary>The hue as a fraction of a turn (0 for greys), with the largest and smallest channel.</summary>
  static (float Hue, float Max, float Min) Hue(Color4 c)
  {
    float max = MathF.Max(c.R, MathF.Max(c.G, c.B)), min = MathF.Min(c.R, MathF.Min(c.G, c.B)), d = max - min;
    float h = d == 0 ? 0f
      : max == c.R ? (c.G - c.B) / d % 6f
      : max == c.G ? (c.B - c.R) / d + 2f
      : (c.R - c.G) / d + 4f;
    if (h < 0) h += 6f;
    return (h / 6f, max, min);
  }

  /// <summary>The RGB of a hue (in sixths of a turn, 0..6) at the given chroma, before the grey offset is added.</summary>
  static (float R, float G, float B) Sector(float h, float chroma)
  {
    float x = chroma * (1f - MathF.Abs(h % 2f - 1f));
    return h switch
    {
      >= 0 and < 1 => (chroma, x, 0),
      >= 1 and < 2 => (x, chroma, 0),
      >= 2 and < 3 => (0, chroma, x),
      >= 3 and < 4 => (0, x, chroma),
      >= 4 and < 5 => (x, 0, chroma),
      >= 5 and <= 6 => (chroma, 0, x),
      _ => (0, 0, 0),
    };
  }
}
