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
  public float R, G, B, A;

  public Color4(float r, float g, float b, float a) { R = r; G = g; B = b; A = a; }
  /// <summary>Each byte over 255.</summary>
  public Color4(byte r, byte g, byte b, byte a) { R = r / 255f; G = g / 255f; B = b / 255f; A = a / 255f; }

  /// <summary>The colour packed as 0xAARRGGBB, each channel times 255 and truncated.</summary>
  public readonly int ToArgb() => unchecked((int)(((uint)(A * 255) << 24) | ((uint)(R * 255) << 16) | ((uint)(G * 255) << 8) | (uint)(B * 255)));

  public static bool operator ==(Color4 left, Color4 right) => left.Equals(right);
  public static bool operator !=(Color4 left, Color4 right) => !left.Equals(right);
  public static implicit operator Color4(System.Drawing.Color color) => new(color.R, color.G, color.B, color.A);
  public static explicit operator System.Drawing.Color(Color4 color) =>
    System.Drawing.Color.FromArgb((int)(color.A * 255), (int)(color.R * 255), (int)(color.G * 255), (int)(color.B * 255));
  public static explicit operator Vector4(Color4 c) => new(c.R, c.G, c.B, c.A);

  public readonly bool Equals(Color4 other) => R == other.R && G == other.G && B == other.B && A == other.A;
  public override readonly bool Equals(object? obj) => obj is Color4 c && Equals(c);
  public override readonly int GetHashCode() => HashCode.Combine(R, G, B, A);
  public override readonly string ToString() => ToString(null, null);
  public readonly string ToString(string? format) => ToString(format, null);
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
  public static Color4 Transparent => new((byte)255, (byte)255, (byte)255, (byte)0);
  public static Color4 AliceBlue => new((byte)240, (byte)248, (byte)255, (byte)255);
  public static Color4 AntiqueWhite => new((byte)250, (byte)235, (byte)215, (byte)255);
  public static Color4 Aqua => new((byte)0, (byte)255, (byte)255, (byte)255);
  public static Color4 Aquamarine => new((byte)127, (byte)255, (byte)212, (byte)255);
  public static Color4 Azure => new((byte)240, (byte)255, (byte)255, (byte)255);
  public static Color4 Beige => new((byte)245, (byte)245, (byte)220, (byte)255);
  public static Color4 Bisque => new((byte)255, (byte)228, (byte)196, (byte)255);
  public static Color4 Black => new((byte)0, (byte)0, (byte)0, (byte)255);
  public static Color4 BlanchedAlmond => new((byte)255, (byte)235, (byte)205, (byte)255);
  public static Color4 Blue => new((byte)0, (byte)0, (byte)255, (byte)255);
  public static Color4 BlueViolet => new((byte)138, (byte)43, (byte)226, (byte)255);
  public static Color4 Brown => new((byte)165, (byte)42, (byte)42, (byte)255);
  public static Color4 BurlyWood => new((byte)222, (byte)184, (byte)135, (byte)255);
  public static Color4 CadetBlue => new((byte)95, (byte)158, (byte)160, (byte)255);
  public static Color4 Chartreuse => new((byte)127, (byte)255, (byte)0, (byte)255);
  public static Color4 Chocolate => new((byte)210, (byte)105, (byte)30, (byte)255);
  public static Color4 Coral => new((byte)255, (byte)127, (byte)80, (byte)255);
  public static Color4 CornflowerBlue => new((byte)100, (byte)149, (byte)237, (byte)255);
  public static Color4 Cornsilk => new((byte)255, (byte)248, (byte)220, (byte)255);
  public static Color4 Crimson => new((byte)220, (byte)20, (byte)60, (byte)255);
  public static Color4 Cyan => new((byte)0, (byte)255, (byte)255, (byte)255);
  public static Color4 DarkBlue => new((byte)0, (byte)0, (byte)139, (byte)255);
  public static Color4 DarkCyan => new((byte)0, (byte)139, (byte)139, (byte)255);
  public static Color4 DarkGoldenrod => new((byte)184, (byte)134, (byte)11, (byte)255);
  public static Color4 DarkGray => new((byte)169, (byte)169, (byte)169, (byte)255);
  public static Color4 DarkGreen => new((byte)0, (byte)100, (byte)0, (byte)255);
  public static Color4 DarkKhaki => new((byte)189, (byte)183, (byte)107, (byte)255);
  public static Color4 DarkMagenta => new((byte)139, (byte)0, (byte)139, (byte)255);
  public static Color4 DarkOliveGreen => new((byte)85, (byte)107, (byte)47, (byte)255);
  public static Color4 DarkOrange => new((byte)255, (byte)140, (byte)0, (byte)255);
  public static Color4 DarkOrchid => new((byte)153, (byte)50, (byte)204, (byte)255);
  public static Color4 DarkRed => new((byte)139, (byte)0, (byte)0, (byte)255);
  public static Color4 DarkSalmon => new((byte)233, (byte)150, (byte)122, (byte)255);
  public static Color4 DarkSeaGreen => new((byte)143, (byte)188, (byte)139, (byte)255);
  public static Color4 DarkSlateBlue => new((byte)72, (byte)61, (byte)139, (byte)255);
  public static Color4 DarkSlateGray => new((byte)47, (byte)79, (byte)79, (byte)255);
  public static Color4 DarkTurquoise => new((byte)0, (byte)206, (byte)209, (byte)255);
  public static Color4 DarkViolet => new((byte)148, (byte)0, (byte)211, (byte)255);
  public static Color4 DeepPink => new((byte)255, (byte)20, (byte)147, (byte)255);
  public static Color4 DeepSkyBlue => new((byte)0, (byte)191, (byte)255, (byte)255);
  public static Color4 DimGray => new((byte)105, (byte)105, (byte)105, (byte)255);
  public static Color4 DodgerBlue => new((byte)30, (byte)144, (byte)255, (byte)255);
  public static Color4 Firebrick => new((byte)178, (byte)34, (byte)34, (byte)255);
  public static Color4 FloralWhite => new((byte)255, (byte)250, (byte)240, (byte)255);
  public static Color4 ForestGreen => new((byte)34, (byte)139, (byte)34, (byte)255);
  public static Color4 Fuchsia => new((byte)255, (byte)0, (byte)255, (byte)255);
  public static Color4 Gainsboro => new((byte)220, (byte)220, (byte)220, (byte)255);
  public static Color4 GhostWhite => new((byte)248, (byte)248, (byte)255, (byte)255);
  public static Color4 Gold => new((byte)255, (byte)215, (byte)0, (byte)255);
  public static Color4 Goldenrod => new((byte)218, (byte)165, (byte)32, (byte)255);
  public static Color4 Gray => new((byte)128, (byte)128, (byte)128, (byte)255);
  public static Color4 Green => new((byte)0, (byte)128, (byte)0, (byte)255);
  public static Color4 GreenYellow => new((byte)173, (byte)255, (byte)47, (byte)255);
  public static Color4 Honeydew => new((byte)240, (byte)255, (byte)240, (byte)255);
  public static Color4 HotPink => new((byte)255, (byte)105, (byte)180, (byte)255);
  public static Color4 IndianRed => new((byte)205, (byte)92, (byte)92, (byte)255);
  public static Color4 Indigo => new((byte)75, (byte)0, (byte)130, (byte)255);
  public static Color4 Ivory => new((byte)255, (byte)255, (byte)240, (byte)255);
  public static Color4 Khaki => new((byte)240, (byte)230, (byte)140, (byte)255);
  public static Color4 Lavender => new((byte)230, (byte)230, (byte)250, (byte)255);
  public static Color4 LavenderBlush => new((byte)255, (byte)240, (byte)245, (byte)255);
  public static Color4 LawnGreen => new((byte)124, (byte)252, (byte)0, (byte)255);
  public static Color4 LemonChiffon => new((byte)255, (byte)250, (byte)205, (byte)255);
  public static Color4 LightBlue => new((byte)173, (byte)216, (byte)230, (byte)255);
  public static Color4 LightCoral => new((byte)240, (byte)128, (byte)128, (byte)255);
  public static Color4 LightCyan => new((byte)224, (byte)255, (byte)255, (byte)255);
  public static Color4 LightGoldenrodYellow => new((byte)250, (byte)250, (byte)210, (byte)255);
  public static Color4 LightGray => new((byte)211, (byte)211, (byte)211, (byte)255);
  public static Color4 LightGreen => new((byte)144, (byte)238, (byte)144, (byte)255);
  public static Color4 LightPink => new((byte)255, (byte)182, (byte)193, (byte)255);
  public static Color4 LightSalmon => new((byte)255, (byte)160, (byte)122, (byte)255);
  public static Color4 LightSeaGreen => new((byte)32, (byte)178, (byte)170, (byte)255);
  public static Color4 LightSkyBlue => new((byte)135, (byte)206, (byte)250, (byte)255);
  public static Color4 LightSlateGray => new((byte)119, (byte)136, (byte)153, (byte)255);
  public static Color4 LightSteelBlue => new((byte)176, (byte)196, (byte)222, (byte)255);
  public static Color4 LightYellow => new((byte)255, (byte)255, (byte)224, (byte)255);
  public static Color4 Lime => new((byte)0, (byte)255, (byte)0, (byte)255);
  public static Color4 LimeGreen => new((byte)50, (byte)205, (byte)50, (byte)255);
  public static Color4 Linen => new((byte)250, (byte)240, (byte)230, (byte)255);
  public static Color4 Magenta => new((byte)255, (byte)0, (byte)255, (byte)255);
  public static Color4 Maroon => new((byte)128, (byte)0, (byte)0, (byte)255);
  public static Color4 MediumAquamarine => new((byte)102, (byte)205, (byte)170, (byte)255);
  public static Color4 MediumBlue => new((byte)0, (byte)0, (byte)205, (byte)255);
  public static Color4 MediumOrchid => new((byte)186, (byte)85, (byte)211, (byte)255);
  public static Color4 MediumPurple => new((byte)147, (byte)112, (byte)219, (byte)255);
  public static Color4 MediumSeaGreen => new((byte)60, (byte)179, (byte)113, (byte)255);
  public static Color4 MediumSlateBlue => new((byte)123, (byte)104, (byte)238, (byte)255);
  public static Color4 MediumSpringGreen => new((byte)0, (byte)250, (byte)154, (byte)255);
  public static Color4 MediumTurquoise => new((byte)72, (byte)209, (byte)204, (byte)255);
  public static Color4 MediumVioletRed => new((byte)199, (byte)21, (byte)133, (byte)255);
  public static Color4 MidnightBlue => new((byte)25, (byte)25, (byte)112, (byte)255);
  public static Color4 MintCream => new((byte)245, (byte)255, (byte)250, (byte)255);
  public static Color4 MistyRose => new((byte)255, (byte)228, (byte)225, (byte)255);
  public static Color4 Moccasin => new((byte)255, (byte)228, (byte)181, (byte)255);
  public static Color4 NavajoWhite => new((byte)255, (byte)222, (byte)173, (byte)255);
  public static Color4 Navy => new((byte)0, (byte)0, (byte)128, (byte)255);
  public static Color4 OldLace => new((byte)253, (byte)245, (byte)230, (byte)255);
  public static Color4 Olive => new((byte)128, (byte)128, (byte)0, (byte)255);
  public static Color4 OliveDrab => new((byte)107, (byte)142, (byte)35, (byte)255);
  public static Color4 Orange => new((byte)255, (byte)165, (byte)0, (byte)255);
  public static Color4 OrangeRed => new((byte)255, (byte)69, (byte)0, (byte)255);
  public static Color4 Orchid => new((byte)218, (byte)112, (byte)214, (byte)255);
  public static Color4 PaleGoldenrod => new((byte)238, (byte)232, (byte)170, (byte)255);
  public static Color4 PaleGreen => new((byte)152, (byte)251, (byte)152, (byte)255);
  public static Color4 PaleTurquoise => new((byte)175, (byte)238, (byte)238, (byte)255);
  public static Color4 PaleVioletRed => new((byte)219, (byte)112, (byte)147, (byte)255);
  public static Color4 PapayaWhip => new((byte)255, (byte)239, (byte)213, (byte)255);
  public static Color4 PeachPuff => new((byte)255, (byte)218, (byte)185, (byte)255);
  public static Color4 Peru => new((byte)205, (byte)133, (byte)63, (byte)255);
  public static Color4 Pink => new((byte)255, (byte)192, (byte)203, (byte)255);
  public static Color4 Plum => new((byte)221, (byte)160, (byte)221, (byte)255);
  public static Color4 PowderBlue => new((byte)176, (byte)224, (byte)230, (byte)255);
  public static Color4 Purple => new((byte)128, (byte)0, (byte)128, (byte)255);
  public static Color4 Red => new((byte)255, (byte)0, (byte)0, (byte)255);
  public static Color4 RosyBrown => new((byte)188, (byte)143, (byte)143, (byte)255);
  public static Color4 RoyalBlue => new((byte)65, (byte)105, (byte)225, (byte)255);
  public static Color4 SaddleBrown => new((byte)139, (byte)69, (byte)19, (byte)255);
  public static Color4 Salmon => new((byte)250, (byte)128, (byte)114, (byte)255);
  public static Color4 SandyBrown => new((byte)244, (byte)164, (byte)96, (byte)255);
  public static Color4 SeaGreen => new((byte)46, (byte)139, (byte)87, (byte)255);
  public static Color4 SeaShell => new((byte)255, (byte)245, (byte)238, (byte)255);
  public static Color4 Sienna => new((byte)160, (byte)82, (byte)45, (byte)255);
  public static Color4 Silver => new((byte)192, (byte)192, (byte)192, (byte)255);
  public static Color4 SkyBlue => new((byte)135, (byte)206, (byte)235, (byte)255);
  public static Color4 SlateBlue => new((byte)106, (byte)90, (byte)205, (byte)255);
  public static Color4 SlateGray => new((byte)112, (byte)128, (byte)144, (byte)255);
  public static Color4 Snow => new((byte)255, (byte)250, (byte)250, (byte)255);
  public static Color4 SpringGreen => new((byte)0, (byte)255, (byte)127, (byte)255);
  public static Color4 SteelBlue => new((byte)70, (byte)130, (byte)180, (byte)255);
  public static Color4 Tan => new((byte)210, (byte)180, (byte)140, (byte)255);
  public static Color4 Teal => new((byte)0, (byte)128, (byte)128, (byte)255);
  public static Color4 Thistle => new((byte)216, (byte)191, (byte)216, (byte)255);
  public static Color4 Tomato => new((byte)255, (byte)99, (byte)71, (byte)255);
  public static Color4 Turquoise => new((byte)64, (byte)224, (byte)208, (byte)255);
  public static Color4 Violet => new((byte)238, (byte)130, (byte)238, (byte)255);
  public static Color4 Wheat => new((byte)245, (byte)222, (byte)179, (byte)255);
  public static Color4 White => new((byte)255, (byte)255, (byte)255, (byte)255);
  public static Color4 WhiteSmoke => new((byte)245, (byte)245, (byte)245, (byte)255);
  public static Color4 Yellow => new((byte)255, (byte)255, (byte)0, (byte)255);
  public static Color4 YellowGreen => new((byte)154, (byte)205, (byte)50, (byte)255);
}
