using System;
using System.IO;
using MathSupport;
using Rendering.Imaging;

namespace Rendering;

/// <summary>
/// An image mapped by the hit's texture coordinates: (u, v) = (0, 0) is the image's bottom-left corner,
/// (1, 1) its top-right one (the OpenGL and Wavefront OBJ convention, so the <c>vt</c> coordinates of an OBJ
/// mesh fit its texture). <see cref="Fu"/>, <see cref="Fv"/>, <see cref="OffsetU"/> and <see cref="OffsetV"/> transform
/// (u, v) first; <see cref="WrapU"/> and <see cref="WrapV"/> say what lies outside [0, 1]; filtering is
/// bilinear between texel centres, or nearest.
/// The texture replaces the surface colour (or multiplies it, <see cref="Multiply"/>), keeping its number
/// of bands: a gray image fills every band, a one-band surface takes the mean of the image's bands,
/// otherwise band b takes the image's band b (its last one when it has fewer).
/// </summary>
/// <remarks>
/// The image is read once and only read afterwards, so one texture serves every render thread and is
/// not cloned for them; a subclass that must clone itself (an animated one) should use
/// <c>MemberwiseClone</c>, which shares <see cref="Image"/>. Textures of the same file share one image.
/// </remarks>
public class ImageTexture : ITexture
{
  /// <summary>Repetitions of the image per texture-coordinate unit in u and v (1: the image spans [0, 1]).</summary>
  public double Fu = 1.0, Fv = 1.0;

  /// <summary>Added to the scaled coordinates, in image units: OffsetU = 0.5 shifts the image by half its width.</summary>
  public double OffsetU, OffsetV;

  /// <summary>Bilinear interpolation between the four nearest texel centres (default); false: the nearest texel.</summary>
  public bool Bilinear = true;

  /// <summary>Multiply the surface colour by the image instead of replacing it (a tint or a dirt map over COLOR).</summary>
  public bool Multiply;

  /// <summary>The pixels (linear values, top row first), shared by every copy of this texture; do not modify while rendering.</summary>
  public FloatImage Image { get; }

  /// <summary>The file the image was read from (as found, e.g. beside the script), or null for an image given in memory.</summary>
  public string? FileName { get; }

  TextureWrap wrapU, wrapV;

  /// <summary>Outside [0, 1] along u (default <see cref="TextureWrap.Repeat"/>).</summary>
  public TextureWrap WrapU
  {
    get => wrapU;
    set => wrapU = Checked(value);
  }

  /// <summary>Outside [0, 1] along v (default <see cref="TextureWrap.Repeat"/>).</summary>
  public TextureWrap WrapV
  {
    get => wrapV;
    set => wrapV = Checked(value);
  }

  // Read per hit: cached out of Image.
  readonly float[] data;
  readonly int width, height, bands;

  /// <summary>
  /// Reads an image file: PNG, JPEG, BMP, TGA, GIF, PSD, Radiance HDR or PFM. A relative path is found as
  /// meshes are, also beside the running script and with <c>\</c> read as a separator.
  /// HDR and PFM values are used as stored (linear, may exceed 1). An 8-bit file's byte c becomes
  /// (c / 255)^<paramref name="gamma"/>: with gamma 1 (default) the texel is the colour a COLOR attribute of
  /// c / 255 would give, as GrCis's colours are used as they are and gamma is applied only to the output;
  /// use 2.2 for a photograph, whose bytes carry a display gamma that the output would otherwise apply twice.
  /// </summary>
  /// <exception cref="FileNotFoundException">No such file; the message names it and the folders searched.</exception>
  /// <exception cref="InvalidDataException">A corrupt or unsupported file; the message starts with the path.</exception>
  public ImageTexture(string fileName, double gamma = 1.0)
    : this(LoadImage(fileName, gamma, out string path))
  {
    FileName = path;
  }

  /// <summary>Uses <paramref name="image"/> (any number of bands) without copying it.</summary>
  public ImageTexture(FloatImage image)
  {
    ArgumentNullException.ThrowIfNull(image);
    Image = image;
    data = image.Data;
    width = image.Width;
    height = image.Height;
    bands = image.Bands;
  }

  static FloatImage LoadImage(string fileName, double gamma, out string path)
  {
    ArgumentException.ThrowIfNullOrEmpty(fileName);
    path = Utilities.DataFiles.Resolve(fileName);
    if (!File.Exists(path))
      throw NotFound(fileName);
    return TextureImageCache.Load(path, gamma);
  }

  // Names what the script wrote and every folder searched (the system's message names only the first).
  static FileNotFoundException NotFound(string fileName)
  {
    string? script = Utilities.DataFiles.ScriptDirectory;
    string where = Path.IsPathRooted(fileName) ? ""
      : script != null ? $" (looked in {Environment.CurrentDirectory} and beside the script in {script}, in any letter case, and in the folders above as from GrCis's bin/Debug)"
      : $" (looked in {Environment.CurrentDirectory}, in any letter case, and in the folders above as from GrCis's bin/Debug)";
    return new FileNotFoundException($"Image file not found: '{fileName}'{where}", fileName);
  }

  /// <summary>
  /// Samples the image at the hit's <see cref="Intersection.TextureCoord"/> (<see cref="Sample"/>) and puts the result in
  /// the surface colour (multiplied by the old one with <see cref="Multiply"/>), keeping its number of bands. Returns
  /// a hash of the nearest texel.
  /// </summary>
  /// <param name="inter">A completed hit.</param>
  public virtual long Apply(Intersection inter)
  {
    double[]? surface = inter.SurfaceColor;
    int n = surface?.Length ?? 3;
    Span<double> color = n <= 8 ? stackalloc double[8] : new double[n];
    color = color[..n];
    long hash = Sample(inter.TextureCoord.X, inter.TextureCoord.Y, color);
    if (Multiply && surface != null)
      for (int b = 0; b < n; b++)
        color[b] *= surface[b];
    // A pooled hit takes the values into its own colour array; any other gets a new one, as GrCis's textures do.
    if (!inter.TryCopySurfaceColor(color))
      inter.SurfaceColor = color.ToArray();
    inter.textureApplied = true;
    return hash;
  }

  /// <summary>
  /// The texture's value at texture coordinates (u, v) (scale, offset, wrap and filter applied) in
  /// <paramref name="color"/>'s bands; returns a hash of the nearest texel.
  /// </summary>
  public long Sample(double u, double v, Span<double> color)
  {
    // Texels from the left and from the bottom edge; row j from the bottom is image row height-1-j.
    double s = (Fu * u + OffsetU) * width;
    double t = (Fv * v + OffsetV) * height;
    int x0, x1, y0, y1;
    double fx, fy;
    if (Bilinear)
    {
      // Between texel centres: the four around (s, t), weighted by the fractions past the lower ones.
      s -= 0.5;
      t -= 0.5;
      double fs = Math.Floor(s), ft = Math.Floor(t);
      fx = s - fs;
      fy = t - ft;
      if (!(fx >= 0.0)) fx = 0.0; // NaN or infinite coordinates: one texel, not NaN
      if (!(fy >= 0.0)) fy = 0.0;
      long i = (long)fs, j = (long)ft;
      x0 = Wrap(i, width, wrapU);
      x1 = Wrap(unchecked(i + 1), width, wrapU);
      y0 = height - 1 - Wrap(j, height, wrapV);
      y1 = height - 1 - Wrap(unchecked(j + 1), height, wrapV);
    }
    else
    {
      x0 = x1 = Wrap((long)Math.Floor(s), width, wrapU);
      y0 = y1 = height - 1 - Wrap((long)Math.Floor(t), height, wrapV);
      fx = fy = 0.0;
    }

    int p00 = (y0 * width + x0) * bands, p10 = (y0 * width + x1) * bands;
    int p01 = (y1 * width + x0) * bands, p11 = (y1 * width + x1) * bands;
    double w00 = (1.0 - fx) * (1.0 - fy), w10 = fx * (1.0 - fy), w01 = (1.0 - fx) * fy, w11 = fx * fy;
    bool mean = color.Length == 1 && bands > 1;
    for (int b = 0; b < color.Length; b++)
    {
      int first = mean ? 0 : Math.Min(b, bands - 1), last = mean ? bands - 1 : first;
      double sum = 0.0;
      for (int k = first; k <= last; k++)
        sum += w00 * data[p00 + k] + w10 * data[p10 + k] + w01 * data[p01 + k] + w11 * data[p11 + k];
      color[b] = mean ? sum / bands : sum;
    }

    int xn = fx >= 0.5 ? x1 : x0, yn = fy >= 0.5 ? y1 : y0;
    return (long)RandomStatic.numericRecipes((ulong)(yn * (long)width + xn));
  }

  /// <summary>Texel index <paramref name="i"/> (any integer) folded into 0 … n−1 as <paramref name="mode"/> says.</summary>
  static int Wrap(long i, int n, TextureWrap mode)
  {
    switch (mode)
    {
      case TextureWrap.Clamp:
        return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
      case TextureWrap.MirroredRepeat:
        long period = 2L * n, m = i % period;
        if (m < 0)
          m += period;
        return (int)(m < n ? m : period - 1 - m);
      default:
        long r = i % n;
        return (int)(r < 0 ? r + n : r);
    }
  }

  static TextureWrap Checked(TextureWrap mode) => Enum.IsDefined(mode)
    ? mode
    : throw new ArgumentOutOfRangeException(nameof(mode), mode, "Wrap mode must be Repeat, MirroredRepeat or Clamp.");
}
