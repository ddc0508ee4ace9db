using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK 4's colour of four floats (linear RGB and alpha, 0..1 for displayable colours), with the conversions to and
/// from sRGB, HSL, HSV, CIE XYZ, YCbCr and HCY (hue, chroma, luma) and the named web colours.
/// </summary>
[Serializable]
public partial struct Color4 : IEquatable<Color4>, IFormattable
{
  /// <summary>The red, green, blue and alpha channels, 0..1 for displayable colours (alpha 1 is opaque).</summary>
  public float R, G, B, A;

  /// <summary>The colour with channels r, g, b and alpha a, as given (no clamping).</summary>
  public Color4(float r, float g, float b, float a) { R = r; G = g; B = b; A = a; }
  /// <summary>Each byte over 255.</summary>
  public Color4(byte r, byte g, byte b, byte a) { R = r / 255f; G = g / 255f; B = b / 255f; A = a / 255f; }

  /// <summary>The colour packed as 0xAARRGGBB, each channel times 255 and truncated.</summary>
  public readonly int ToArgb() => unchecked((int)(((uint)(A * 255) << 24) | ((uint)(R * 255) << 16) | ((uint)(G * 255) << 8) | (uint)(B * 255)));

  /// <summary>Whether the two are equal, as <see cref="Equals(Color4)"/> compares them.</summary>
  public static bool operator ==(Color4 left, Color4 right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Color4)"/>.</summary>
  public static bool operator !=(Color4 left, Color4 right) => !left.Equals(right);
  /// <summary>The System.Drawing colour's bytes, each over 255.</summary>
  public static implicit operator Color4(System.Drawing.Color color) => new(color.R, color.G, color.B, color.A);
  /// <summary>Each channel times 255, truncated; a channel outside 0..1 makes
  /// <see cref="System.Drawing.Color.FromArgb(int, int, int, int)"/> throw
  /// <see cref="System.ArgumentException"/>.</summary>
  public static explicit operator System.Drawing.Color(Color4 color) =>
    System.Drawing.Color.FromArgb((int)(color.A * 255), (int)(color.R * 255), (int)(color.G * 255), (int)(color.B * 255));
  /// <summary>The channels as (R, G, B, A).</summary>
  public static explicit operator Vector4(Color4 c) => new(c.R, c.G, c.B, c.A);

  /// <summary>Whether every channel equals the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Color4 other) => R == other.R && G == other.G && B == other.B && A == other.A;
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Color4 c && Equals(c);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(R, G, B, A);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(null, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with the current culture.</summary>
  public readonly string ToString(string? format) => ToString(format, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with no format.</summary>
  public readonly string ToString(IFormatProvider? formatProvider) => ToString(null, formatProvider);
  /// <summary>OpenTK's form, <c>{(R, G, B, A) = (r, g, b, a)}</c>, with the culture's list separator.</summary>
  public readonly string ToString(string? format, IFormatProvider? formatProvider)
  {
    formatProvider ??= CultureInfo.CurrentCulture;
    string ls = (formatProvider as CultureInfo ?? CultureInfo.CurrentCulture).TextInfo.ListSeparator;
    return $"{{(R{ls} G{ls} B{ls} A) = ({R.ToString(format, formatProvider)}{ls} {G.ToString(format, formatProvider)}{ls} " +
      $"{B.ToString(format, formatProvider)}{ls} {A.ToString(format, formatProvider)})}}";
  }

  // The named colours (OpenTK's list: the web colours and Transparent, a transparent white).
  /// <summary>Transparent white: bytes (255, 255, 255) over 255 with alpha 0.</summary>
  public static Color4 Transparent => new((byte)255, (byte)255, (byte)255, (byte)0);
  /// <summary>The web colour alice blue: bytes (240, 248, 255) over 255, opaque.</summary>
  public static Color4 AliceBlue => new((byte)240, (byte)248, (byte)255, (byte)255);
  /// <summary>The web colour antique white: bytes (250, 235, 215) over 255, opaque.</summary>
  public static Color4 AntiqueWhite => new((byte)250, (byte)235, (byte)215, (byte)255);
  /// <summary>The web colour aqua: bytes (0, 255, 255) over 255, opaque.</summary>
  public static Color4 Aqua => new((byte)0, (byte)255, (byte)255, (byte)255);
  /// <summary>The web colour aquamarine: bytes (127, 255, 212) over 255, opaque.</summary>
  public static Color4 Aquamarine => new((byte)127, (byte)255, (byte)212, (byte)255);
  /// <summary>The web colour azure: bytes (240, 255, 255) over 255, opaque.</summary>
  public static Color4 Azure => new((byte)240, (byte)255, (byte)255, (byte)255);
  /// <summary>The web colour beige: bytes (245, 245, 220) over 255, opaque.</summary>
  public static Color4 Beige => new((byte)245, (byte)245, (byte)220, (byte)255);
  /// <summary>The web colour bisque: bytes (255, 228, 196) over 255, opaque.</summary>
  public static Color4 Bisque => new((byte)255, (byte)228, (byte)196, (byte)255);
  /// <summary>The web colour black: bytes (0, 0, 0) over 255, opaque.</summary>
  public static Color4 Black => new((byte)0, (byte)0, (byte)0, (byte)255);
  /// <summary>The web colour blanched almond: bytes (255, 235, 205) over 255, opaque.</summary>
  public static Color4 BlanchedAlmond => new((byte)255, (byte)235, (byte)205, (byte)255);
  /// <summary>The web colour blue: bytes (0, 0, 255) over 255, opaque.</summary>
  public static Color4 Blue => new((byte)0, (byte)0, (byte)255, (byte)255);
  /// <summary>The web colour blue violet: bytes (138, 43, 226) over 255, opaque.</summary>
  public static Color4 BlueViolet => new((byte)138, (byte)43, (byte)226, (byte)255);
  /// <summary>The web colour brown: bytes (165, 42, 42) over 255, opaque.</summary>
  public static Color4 Brown => new((byte)165, (byte)42, (byte)42, (byte)255);
  /// <summary>The web colour burly wood: bytes (222, 184, 135) over 255, opaque.</summary>
  public static Color4 BurlyWood => new((byte)222, (byte)184, (byte)135, (byte)255);
  /// <summary>The web colour cadet blue: bytes (95, 158, 160) over 255, opaque.</summary>
  public static Color4 CadetBlue => new((byte)95, (byte)158, (byte)160, (byte)255);
  /// <summary>The web colour chartreuse: bytes (127, 255, 0) over 255, opaque.</summary>
  public static Color4 Chartreuse => new((byte)127, (byte)255, (byte)0, (byte)255);
  /// <summary>The web colour chocolate: bytes (210, 105, 30) over 255, opaque.</summary>
  public static Color4 Chocolate => new((byte)210, (byte)105, (byte)30, (byte)255);
  /// <summary>The web colour coral: bytes (255, 127, 80) over 255, opaque.</summary>
  public static Color4 Coral => new((byte)255, (byte)127, (byte)80, (byte)255);
  /// <summary>The web colour cornflower blue: bytes (100, 149, 237) over 255, opaque.</summary>
  public static Color4 CornflowerBlue => new((byte)100, (byte)149, (byte)237, (byte)255);
  /// <summary>The web colour cornsilk: bytes (255, 248, 220) over 255, opaque.</summary>
  public static Color4 Cornsilk => new((byte)255, (byte)248, (byte)220, (byte)255);
  /// <summary>The web colour crimson: bytes (220, 20, 60) over 255, opaque.</summary>
  public static Color4 Crimson => new((byte)220, (byte)20, (byte)60, (byte)255);
  /// <summary>The web colour cyan: bytes (0, 255, 255) over 255, opaque.</summary>
  public static Color4 Cyan => new((byte)0, (byte)255, (byte)255, (byte)255);
  /// <summary>The web colour dark blue: bytes (0, 0, 139) over 255, opaque.</summary>
  public static Color4 DarkBlue => new((byte)0, (byte)0, (byte)139, (byte)255);
  /// <summary>The web colour dark cyan: bytes (0, 139, 139) over 255, opaque.</summary>
  public static Color4 DarkCyan => new((byte)0, (byte)139, (byte)139, (byte)255);
  /// <summary>The web colour dark goldenrod: bytes (184, 134, 11) over 255, opaque.</summary>
  public static Color4 DarkGoldenrod => new((byte)184, (byte)134, (byte)11, (byte)255);
  /// <summary>The web colour dark gray: bytes (169, 169, 169) over 255, opaque.</summary>
  public static Color4 DarkGray => new((byte)169, (byte)169, (byte)169, (byte)255);
  /// <summary>The web colour dark green: bytes (0, 100, 0) over 255, opaque.</summary>
  public static Color4 DarkGreen => new((byte)0, (byte)100, (byte)0, (byte)255);
  /// <summary>The web colour dark khaki: bytes (189, 183, 107) over 255, opaque.</summary>
  public static Color4 DarkKhaki => new((byte)189, (byte)183, (byte)107, (byte)255);
  /// <summary>The web colour dark magenta: bytes (139, 0, 139) over 255, opaque.</summary>
  public static Color4 DarkMagenta => new((byte)139, (byte)0, (byte)139, (byte)255);
  /// <summary>The web colour dark olive green: bytes (85, 107, 47) over 255, opaque.</summary>
  public static Color4 DarkOliveGreen => new((byte)85, (byte)107, (byte)47, (byte)255);
  /// <summary>The web colour dark orange: bytes (255, 140, 0) over 255, opaque.</summary>
  public static Color4 DarkOrange => new((byte)255, (byte)140, (byte)0, (byte)255);
  /// <summary>The web colour dark orchid: bytes (153, 50, 204) over 255, opaque.</summary>
  public static Color4 DarkOrchid => new((byte)153, (byte)50, (byte)204, (byte)255);
  /// <summary>The web colour dark red: bytes (139, 0, 0) over 255, opaque.</summary>
  public static Color4 DarkRed => new((byte)139, (byte)0, (byte)0, (byte)255);
  /// <summary>The web colour dark salmon: bytes (233, 150, 122) over 255, opaque.</summary>
  public static Color4 DarkSalmon => new((byte)233, (byte)150, (byte)122, (byte)255);
  /// <summary>The web colour dark sea green: bytes (143, 188, 139) over 255, opaque.</summary>
  public static Color4 DarkSeaGreen => new((byte)143, (byte)188, (byte)139, (byte)255);
  /// <summary>The web colour dark slate blue: bytes (72, 61, 139) over 255, opaque.</summary>
  public static Color4 DarkSlateBlue => new((byte)72, (byte)61, (byte)139, (byte)255);
  /// <summary>The web colour dark slate gray: bytes (47, 79, 79) over 255, opaque.</summary>
  public static Color4 DarkSlateGray => new((byte)47, (byte)79, (byte)79, (byte)255);
  /// <summary>The web colour dark turquoise: bytes (0, 206, 209) over 255, opaque.</summary>
  public static Color4 DarkTurquoise => new((byte)0, (byte)206, (byte)209, (byte)255);
  /// <summary>The web colour dark violet: bytes (148, 0, 211) over 255, opaque.</summary>
  public static Color4 DarkViolet => new((byte)148, (byte)0, (byte)211, (byte)255);
  /// <summary>The web colour deep pink: bytes (255, 20, 147) over 255, opaque.</summary>
  public static Color4 DeepPink => new((byte)255, (byte)20, (byte)147, (byte)255);
  /// <summary>The web colour deep sky blue: bytes (0, 191, 255) over 255, opaque.</summary>
  public static Color4 DeepSkyBlue => new((byte)0, (byte)191, (byte)255, (byte)255);
  /// <summary>The web colour dim gray: bytes (105, 105, 105) over 255, opaque.</summary>
  public static Color4 DimGray => new((byte)105, (byte)105, (byte)105, (byte)255);
  /// <summary>The web colour dodger blue: bytes (30, 144, 255) over 255, opaque.</summary>
  public static Color4 DodgerBlue => new((byte)30, (byte)144, (byte)255, (byte)255);
  /// <summary>The web colour firebrick: bytes (178, 34, 34) over 255, opaque.</summary>
  public static Color4 Firebrick => new((byte)178, (byte)34, (byte)34, (byte)255);
  /// <summary>The web colour floral white: bytes (255, 250, 240) over 255, opaque.</summary>
  public static Color4 FloralWhite => new((byte)255, (byte)250, (byte)240, (byte)255);
  /// <summary>The web colour forest green: bytes (34, 139, 34) over 255, opaque.</summary>
  public static Color4 ForestGreen => new((byte)34, (byte)139, (byte)34, (byte)255);
  /// <summary>The web colour fuchsia: bytes (255, 0, 255) over 255, opaque.</summary>
  public static Color4 Fuchsia => new((byte)255, (byte)0, (byte)255, (byte)255);
  /// <summary>The web colour gainsboro: bytes (220, 220, 220) over 255, opaque.</summary>
  public static Color4 Gainsboro => new((byte)220, (byte)220, (byte)220, (byte)255);
  /// <summary>The web colour ghost white: bytes (248, 248, 255) over 255, opaque.</summary>
  public static Color4 GhostWhite => new((byte)248, (byte)248, (byte)255, (byte)255);
  /// <summary>The web colour gold: bytes (255, 215, 0) over 255, opaque.</summary>
  public static Color4 Gold => new((byte)255, (byte)215, (byte)0, (byte)255);
  /// <summary>The web colour goldenrod: bytes (218, 165, 32) over 255, opaque.</summary>
  public static Color4 Goldenrod => new((byte)218, (byte)165, (byte)32, (byte)255);
  /// <summary>The web colour gray: bytes (128, 128, 128) over 255, opaque.</summary>
  public static Color4 Gray => new((byte)128, (byte)128, (byte)128, (byte)255);
  /// <summary>The web colour green: bytes (0, 128, 0) over 255, opaque.</summary>
  public static Color4 Green => new((byte)0, (byte)128, (byte)0, (byte)255);
  /// <summary>The web colour green yellow: bytes (173, 255, 47) over 255, opaque.</summary>
  public static Color4 GreenYellow => new((byte)173, (byte)255, (byte)47, (byte)255);
  /// <summary>The web colour honeydew: bytes (240, 255, 240) over 255, opaque.</summary>
  public static Color4 Honeydew => new((byte)240, (byte)255, (byte)240, (byte)255);
  /// <summary>The web colour hot pink: bytes (255, 105, 180) over 255, opaque.</summary>
  public static Color4 HotPink => new((byte)255, (byte)105, (byte)180, (byte)255);
  /// <summary>The web colour indian red: bytes (205, 92, 92) over 255, opaque.</summary>
  public static Color4 IndianRed => new((byte)205, (byte)92, (byte)92, (byte)255);
  /// <summary>The web colour indigo: bytes (75, 0, 130) over 255, opaque.</summary>
  public static Color4 Indigo => new((byte)75, (byte)0, (byte)130, (byte)255);
  /// <summary>The web colour ivory: bytes (255, 255, 240) over 255, opaque.</summary>
  public static Color4 Ivory => new((byte)255, (byte)255, (byte)240, (byte)255);
  /// <summary>The web colour khaki: bytes (240, 230, 140) over 255, opaque.</summary>
  public static Color4 Khaki => new((byte)240, (byte)230, (byte)140, (byte)255);
  /// <summary>The web colour lavender: bytes (230, 230, 250) over 255, opaque.</summary>
  public static Color4 Lavender => new((byte)230, (byte)230, (byte)250, (byte)255);
  /// <summary>The web colour lavender blush: bytes (255, 240, 245) over 255, opaque.</summary>
  public static Color4 LavenderBlush => new((byte)255, (byte)240, (byte)245, (byte)255);
  /// <summary>The web colour lawn green: bytes (124, 252, 0) over 255, opaque.</summary>
  public static Color4 LawnGreen => new((byte)124, (byte)252, (byte)0, (byte)255);
  /// <summary>The web colour lemon chiffon: bytes (255, 250, 205) over 255, opaque.</summary>
  public static Color4 LemonChiffon => new((byte)255, (byte)250, (byte)205, (byte)255);
  /// <summary>The web colour light blue: bytes (173, 216, 230) over 255, opaque.</summary>
  public static Color4 LightBlue => new((byte)173, (byte)216, (byte)230, (byte)255);
  /// <summary>The web colour light coral: bytes (240, 128, 128) over 255, opaque.</summary>
  public static Color4 LightCoral => new((byte)240, (byte)128, (byte)128, (byte)255);
  /// <summary>The web colour light cyan: bytes (224, 255, 255) over 255, opaque.</summary>
  public static Color4 LightCyan => new((byte)224, (byte)255, (byte)255, (byte)255);
  /// <summary>The web colour light goldenrod yellow: bytes (250, 250, 210) over 255, opaque.</summary>
  public static Color4 LightGoldenrodYellow => new((byte)250, (byte)250, (byte)210, (byte)255);
  /// <summary>The web colour light gray: bytes (211, 211, 211) over 255, opaque.</summary>
  public static Color4 LightGray => new((byte)211, (byte)211, (byte)211, (byte)255);
  /// <summary>The web colour light green: bytes (144, 238, 144) over 255, opaque.</summary>
  public static Color4 LightGreen => new((byte)144, (byte)238, (byte)144, (byte)255);
  /// <summary>The web colour light pink: bytes (255, 182, 193) over 255, opaque.</summary>
  public static Color4 LightPink => new((byte)255, (byte)182, (byte)193, (byte)255);
  /// <summary>The web colour light salmon: bytes (255, 160, 122) over 255, opaque.</summary>
  public static Color4 LightSalmon => new((byte)255, (byte)160, (byte)122, (byte)255);
  /// <summary>The web colour light sea green: bytes (32, 178, 170) over 255, opaque.</summary>
  public static Color4 LightSeaGreen => new((byte)32, (byte)178, (byte)170, (byte)255);
  /// <summary>The web colour light sky blue: bytes (135, 206, 250) over 255, opaque.</summary>
  public static Color4 LightSkyBlue => new((byte)135, (byte)206, (byte)250, (byte)255);
  /// <summary>The web colour light slate gray: bytes (119, 136, 153) over 255, opaque.</summary>
  public static Color4 LightSlateGray => new((byte)119, (byte)136, (byte)153, (byte)255);
  /// <summary>The web colour light steel blue: bytes (176, 196, 222) over 255, opaque.</summary>
  public static Color4 LightSteelBlue => new((byte)176, (byte)196, (byte)222, (byte)255);
  /// <summary>The web colour light yellow: bytes (255, 255, 224) over 255, opaque.</summary>
  public static Color4 LightYellow => new((byte)255, (byte)255, (byte)224, (byte)255);
  /// <summary>The web colour lime: bytes (0, 255, 0) over 255, opaque.</summary>
  public static Color4 Lime => new((byte)0, (byte)255, (byte)0, (byte)255);
  /// <summary>The web colour lime green: bytes (50, 205, 50) over 255, opaque.</summary>
  public static Color4 LimeGreen => new((byte)50, (byte)205, (byte)50, (byte)255);
  /// <summary>The web colour linen: bytes (250, 240, 230) over 255, opaque.</summary>
  public static Color4 Linen => new((byte)250, (byte)240, (byte)230, (byte)255);
  /// <summary>The web colour magenta: bytes (255, 0, 255) over 255, opaque.</summary>
  public static Color4 Magenta => new((byte)255, (byte)0, (byte)255, (byte)255);
  /// <summary>The web colour maroon: bytes (128, 0, 0) over 255, opaque.</summary>
  public static Color4 Maroon => new((byte)128, (byte)0, (byte)0, (byte)255);
  /// <summary>The web colour medium aquamarine: bytes (102, 205, 170) over 255, opaque.</summary>
  public static Color4 MediumAquamarine => new((byte)102, (byte)205, (byte)170, (byte)255);
  /// <summary>The web colour medium blue: bytes (0, 0, 205) over 255, opaque.</summary>
  public static Color4 MediumBlue => new((byte)0, (byte)0, (byte)205, (byte)255);
  /// <summary>The web colour medium orchid: bytes (186, 85, 211) over 255, opaque.</summary>
  public static Color4 MediumOrchid => new((byte)186, (byte)85, (byte)211, (byte)255);
  /// <summary>The web colour medium purple: bytes (147, 112, 219) over 255, opaque.</summary>
  public static Color4 MediumPurple => new((byte)147, (byte)112, (byte)219, (byte)255);
  /// <summary>The web colour medium sea green: bytes (60, 179, 113) over 255, opaque.</summary>
  public static Color4 MediumSeaGreen => new((byte)60, (byte)179, (byte)113, (byte)255);
  /// <summary>The web colour medium slate blue: bytes (123, 104, 238) over 255, opaque.</summary>
  public static Color4 MediumSlateBlue => new((byte)123, (byte)104, (byte)238, (byte)255);
  /// <summary>The web colour medium spring green: bytes (0, 250, 154) over 255, opaque.</summary>
  public static Color4 MediumSpringGreen => new((byte)0, (byte)250, (byte)154, (byte)255);
  /// <summary>The web colour medium turquoise: bytes (72, 209, 204) over 255, opaque.</summary>
  public static Color4 MediumTurquoise => new((byte)72, (byte)209, (byte)204, (byte)255);
  /// <summary>The web colour medium violet red: bytes (199, 21, 133) over 255, opaque.</summary>
  public static Color4 MediumVioletRed => new((byte)199, (byte)21, (byte)133, (byte)255);
  /// <summary>The web colour midnight blue: bytes (25, 25, 112) over 255, opaque.</summary>
  public static Color4 MidnightBlue => new((byte)25, (byte)25, (byte)112, (byte)255);
  /// <summary>The web colour mint cream: bytes (245, 255, 250) over 255, opaque.</summary>
  public static Color4 MintCream => new((byte)245, (byte)255, (byte)250, (byte)255);
  /// <summary>The web colour misty rose: bytes (255, 228, 225) over 255, opaque.</summary>
  public static Color4 MistyRose => new((byte)255, (byte)228, (byte)225, (byte)255);
  /// <summary>The web colour moccasin: bytes (255, 228, 181) over 255, opaque.</summary>
  public static Color4 Moccasin => new((byte)255, (byte)228, (byte)181, (byte)255);
  /// <summary>The web colour navajo white: bytes (255, 222, 173) over 255, opaque.</summary>
  public static Color4 NavajoWhite => new((byte)255, (byte)222, (byte)173, (byte)255);
  /// <summary>The web colour navy: bytes (0, 0, 128) over 255, opaque.</summary>
  public static Color4 Navy => new((byte)0, (byte)0, (byte)128, (byte)255);
  /// <summary>The web colour old lace: bytes (253, 245, 230) over 255, opaque.</summary>
  public static Color4 OldLace => new((byte)253, (byte)245, (byte)230, (byte)255);
  /// <summary>The web colour olive: bytes (128, 128, 0) over 255, opaque.</summary>
  public static Color4 Olive => new((byte)128, (byte)128, (byte)0, (byte)255);
  /// <summary>The web colour olive drab: bytes (107, 142, 35) over 255, opaque.</summary>
  public static Color4 OliveDrab => new((byte)107, (byte)142, (byte)35, (byte)255);
  /// <summary>The web colour orange: bytes (255, 165, 0) over 255, opaque.</summary>
  public static Color4 Orange => new((byte)255, (byte)165, (byte)0, (byte)255);
  /// <summary>The web colour orange red: bytes (255, 69, 0) over 255, opaque.</summary>
  public static Color4 OrangeRed => new((byte)255, (byte)69, (byte)0, (byte)255);
  /// <summary>The web colour orchid: bytes (218, 112, 214) over 255, opaque.</summary>
  public static Color4 Orchid => new((byte)218, (byte)112, (byte)214, (byte)255);
  /// <summary>The web colour pale goldenrod: bytes (238, 232, 170) over 255, opaque.</summary>
  public static Color4 PaleGoldenrod => new((byte)238, (byte)232, (byte)170, (byte)255);
  /// <summary>The web colour pale green: bytes (152, 251, 152) over 255, opaque.</summary>
  public static Color4 PaleGreen => new((byte)152, (byte)251, (byte)152, (byte)255);
  /// <summary>The web colour pale turquoise: bytes (175, 238, 238) over 255, opaque.</summary>
  public static Color4 PaleTurquoise => new((byte)175, (byte)238, (byte)238, (byte)255);
  /// <summary>The web colour pale violet red: bytes (219, 112, 147) over 255, opaque.</summary>
  public static Color4 PaleVioletRed => new((byte)219, (byte)112, (byte)147, (byte)255);
  /// <summary>The web colour papaya whip: bytes (255, 239, 213) over 255, opaque.</summary>
  public static Color4 PapayaWhip => new((byte)255, (byte)239, (byte)213, (byte)255);
  /// <summary>The web colour peach puff: bytes (255, 218, 185) over 255, opaque.</summary>
  public static Color4 PeachPuff => new((byte)255, (byte)218, (byte)185, (byte)255);
  /// <summary>The web colour peru: bytes (205, 133, 63) over 255, opaque.</summary>
  public static Color4 Peru => new((byte)205, (byte)133, (byte)63, (byte)255);
  /// <summary>The web colour pink: bytes (255, 192, 203) over 255, opaque.</summary>
  public static Color4 Pink => new((byte)255, (byte)192, (byte)203, (byte)255);
  /// <summary>The web colour plum: bytes (221, 160, 221) over 255, opaque.</summary>
  public static Color4 Plum => new((byte)221, (byte)160, (byte)221, (byte)255);
  /// <summary>The web colour powder blue: bytes (176, 224, 230) over 255, opaque.</summary>
  public static Color4 PowderBlue => new((byte)176, (byte)224, (byte)230, (byte)255);
  /// <summary>The web colour purple: bytes (128, 0, 128) over 255, opaque.</summary>
  public static Color4 Purple => new((byte)128, (byte)0, (byte)128, (byte)255);
  /// <summary>The web colour red: bytes (255, 0, 0) over 255, opaque.</summary>
  public static Color4 Red => new((byte)255, (byte)0, (byte)0, (byte)255);
  /// <summary>The web colour rosy brown: bytes (188, 143, 143) over 255, opaque.</summary>
  public static Color4 RosyBrown => new((byte)188, (byte)143, (byte)143, (byte)255);
  /// <summary>The web colour royal blue: bytes (65, 105, 225) over 255, opaque.</summary>
  public static Color4 RoyalBlue => new((byte)65, (byte)105, (byte)225, (byte)255);
  /// <summary>The web colour saddle brown: bytes (139, 69, 19) over 255, opaque.</summary>
  public static Color4 SaddleBrown => new((byte)139, (byte)69, (byte)19, (byte)255);
  /// <summary>The web colour salmon: bytes (250, 128, 114) over 255, opaque.</summary>
  public static Color4 Salmon => new((byte)250, (byte)128, (byte)114, (byte)255);
  /// <summary>The web colour sandy brown: bytes (244, 164, 96) over 255, opaque.</summary>
  public static Color4 SandyBrown => new((byte)244, (byte)164, (byte)96, (byte)255);
  /// <summary>The web colour sea green: bytes (46, 139, 87) over 255, opaque.</summary>
  public static Color4 SeaGreen => new((byte)46, (byte)139, (byte)87, (byte)255);
  /// <summary>The web colour sea shell: bytes (255, 245, 238) over 255, opaque.</summary>
  public static Color4 SeaShell => new((byte)255, (byte)245, (byte)238, (byte)255);
  /// <summary>The web colour sienna: bytes (160, 82, 45) over 255, opaque.</summary>
  public static Color4 Sienna => new((byte)160, (byte)82, (byte)45, (byte)255);
  /// <summary>The web colour silver: bytes (192, 192, 192) over 255, opaque.</summary>
  public static Color4 Silver => new((byte)192, (byte)192, (byte)192, (byte)255);
  /// <summary>The web colour sky blue: bytes (135, 206, 235) over 255, opaque.</summary>
  public static Color4 SkyBlue => new((byte)135, (byte)206, (byte)235, (byte)255);
  /// <summary>The web colour slate blue: bytes (106, 90, 205) over 255, opaque.</summary>
  public static Color4 SlateBlue => new((byte)106, (byte)90, (byte)205, (byte)255);
  /// <summary>The web colour slate gray: bytes (112, 128, 144) over 255, opaque.</summary>
  public static Color4 SlateGray => new((byte)112, (byte)128, (byte)144, (byte)255);
  /// <summary>The web colour snow: bytes (255, 250, 250) over 255, opaque.</summary>
  public static Color4 Snow => new((byte)255, (byte)250, (byte)250, (byte)255);
  /// <summary>The web colour spring green: bytes (0, 255, 127) over 255, opaque.</summary>
  public static Color4 SpringGreen => new((byte)0, (byte)255, (byte)127, (byte)255);
  /// <summary>The web colour steel blue: bytes (70, 130, 180) over 255, opaque.</summary>
  public static Color4 SteelBlue => new((byte)70, (byte)130, (byte)180, (byte)255);
  /// <summary>The web colour tan: bytes (210, 180, 140) over 255, opaque.</summary>
  public static Color4 Tan => new((byte)210, (byte)180, (byte)140, (byte)255);
  /// <summary>The web colour teal: bytes (0, 128, 128) over 255, opaque.</summary>
  public static Color4 Teal => new((byte)0, (byte)128, (byte)128, (byte)255);
  /// <summary>The web colour thistle: bytes (216, 191, 216) over 255, opaque.</summary>
  public static Color4 Thistle => new((byte)216, (byte)191, (byte)216, (byte)255);
  /// <summary>The web colour tomato: bytes (255, 99, 71) over 255, opaque.</summary>
  public static Color4 Tomato => new((byte)255, (byte)99, (byte)71, (byte)255);
  /// <summary>The web colour turquoise: bytes (64, 224, 208) over 255, opaque.</summary>
  public static Color4 Turquoise => new((byte)64, (byte)224, (byte)208, (byte)255);
  /// <summary>The web colour violet: bytes (238, 130, 238) over 255, opaque.</summary>
  public static Color4 Violet => new((byte)238, (byte)130, (byte)238, (byte)255);
  /// <summary>The web colour wheat: bytes (245, 222, 179) over 255, opaque.</summary>
  public static Color4 Wheat => new((byte)245, (byte)222, (byte)179, (byte)255);
  /// <summary>The web colour white: bytes (255, 255, 255) over 255, opaque.</summary>
  public static Color4 White => new((byte)255, (byte)255, (byte)255, (byte)255);
  /// <summary>The web colour white smoke: bytes (245, 245, 245) over 255, opaque.</summary>
  public static Color4 WhiteSmoke => new((byte)245, (byte)245, (byte)245, (byte)255);
  /// <summary>The web colour yellow: bytes (255, 255, 0) over 255, opaque.</summary>
  public static Color4 Yellow => new((byte)255, (byte)255, (byte)0, (byte)255);
  /// <summary>The web colour yellow green: bytes (154, 205, 50) over 255, opaque.</summary>
  public static Color4 YellowGreen => new((byte)154, (byte)205, (byte)50, (byte)255);
}
