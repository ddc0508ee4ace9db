using System;
using System.Globalization;
using System.IO;
using System.Threading;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>
/// Depth, normals and rays-per-pixel maps of a render job, with a value read-out and PNG, CSV and
/// point-cloud (PLY) export. Computed by a separate pass of the job's own image function with an observer
/// attached (<see cref="RenderContext"/>), sampling exactly the renderer's sample positions; the image of
/// that pass is thrown away. The noise map is the render's own estimate, handed in.
/// </summary>
public sealed class ExtraViews
{
  readonly AovObserver maps;
  readonly NoiseImage? noise;

  ExtraViews(int width, int height, AovObserver maps, bool allRaysKnown, NoiseImage? noise)
  {
    Width = width;
    Height = height;
    this.maps = maps;
    AllRaysKnown = allRaysKnown;
    this.noise = noise != null && noise.Width == width && noise.Height == height ? noise : null;
  }

  public int Width { get; }

  public int Height { get; }

  /// <summary>False when the job's image function is not a <see cref="RayTracing"/>: only primary rays were counted.</summary>
  public bool AllRaysKnown { get; }

  /// <summary>Runs the maps pass. Do not call while the same job is rendering (it shares the renderer).</summary>
  /// <param name="noise">The noise estimate of the job's render (<see cref="FrameResult.Noise"/>) for <see cref="MapKind.Noise"/>; null = none.</param>
  public static ExtraViews Compute(RenderJob job, CancellationToken cancel = default, NoiseImage? noise = null)
  {
    ArgumentNullException.ThrowIfNull(job);
    var observer = new AovObserver(job.Width, job.Height);
    bool known = job.ImageFunction is RayTracing;
    // Another image function reports no rays unless it is a RayCasting: its first hits are those of ray
    // casting, so depth and normals come from plain ray casting on the same query path.
    IImageFunction tracer = job.ImageFunction is RayCasting ? job.ImageFunction : new RayCasting();

    ImageSynthesizer renderer = job.Renderer;
    IImageFunction? saved = renderer.ImageFunction;
    try
    {
      TileRenderer.Render(job.Scene, tracer, renderer, job.Options, null, cancel, new RenderContext { Observer = observer });
    }
    finally
    {
      renderer.ImageFunction = saved;
    }
    return new ExtraViews(job.Width, job.Height, observer, known, noise);
  }

  int Index(int x, int y)
  {
    if ((uint)x >= (uint)Width || (uint)y >= (uint)Height)
      throw new ArgumentOutOfRangeException(nameof(x), $"[{x},{y}] is outside the {Width}x{Height} map.");
    return y * Width + x;
  }

  /// <summary>Average distance to the first hit; +∞ where no primary ray hit anything.</summary>
  public double DepthAt(int x, int y)
  {
    int i = Index(x, y);
    return maps.Hits[i] > 0 ? maps.DepthSum[i] / maps.Hits[i] : double.PositiveInfinity;
  }

  /// <summary>Average unit world normal at the first hits; zero where nothing was hit.</summary>
  public Vector3d NormalAt(int x, int y)
  {
    Vector3d n = maps.NormalSum[Index(x, y)];
    double len = n.Length;
    return len > 0.0 ? n / len : Vector3d.Zero;
  }

  /// <summary>Average first-hit point, or null where nothing was hit.</summary>
  public Vector3d? HitPointAt(int x, int y)
  {
    int i = Index(x, y);
    return maps.Hits[i] > 0 ? maps.PointSum[i] / maps.Hits[i] : null;
  }

  /// <summary>Scalar value of a map at (x, y); for <see cref="MapKind.NormalAbsolute"/> the relative angle too.</summary>
  public double ValueAt(MapKind kind, int x, int y)
  {
    int i = Index(x, y);
    return kind switch
    {
      MapKind.Depth => DepthAt(x, y),
      MapKind.NormalRelative or MapKind.NormalAbsolute => maps.Hits[i] > 0 ? maps.AngleSum[i] / maps.Hits[i] : double.NaN,
      MapKind.PrimaryRays => maps.Primary[i],
      MapKind.AllRays => maps.All[i],
      MapKind.Noise => noise?.StandardErrorAt(x, y) ?? double.NaN,
      _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown map."),
    };
  }

  /// <summary>Read-out text for the status line, e.g. "[12,7] depth 5.000".</summary>
  public string Describe(MapKind kind, int x, int y)
  {
    var c = CultureInfo.InvariantCulture;
    return kind switch
    {
      MapKind.Depth => double.IsInfinity(DepthAt(x, y)) ? $"[{x},{y}] depth ∞ (no hit)" : string.Create(c, $"[{x},{y}] depth {DepthAt(x, y):0.####}"),
      MapKind.NormalAbsolute => NormalAt(x, y) is var n && n != Vector3d.Zero
        ? string.Create(c, $"[{x},{y}] normal ({n.X:0.###}, {n.Y:0.###}, {n.Z:0.###})") : $"[{x},{y}] no hit",
      MapKind.NormalRelative => double.IsNaN(ValueAt(kind, x, y)) ? $"[{x},{y}] no hit"
        : string.Create(c, $"[{x},{y}] {ValueAt(kind, x, y):0.#}° from the view direction"),
      MapKind.PrimaryRays => $"[{x},{y}] {ValueAt(kind, x, y)} primary rays",
      MapKind.Noise => double.IsNaN(ValueAt(kind, x, y)) ? $"[{x},{y}] no noise estimate (it needs 2x2 samples per pixel or more)"
        : string.Create(c, $"[{x},{y}] noise ±{ValueAt(kind, x, y):0.#####} (standard error of the linear value)"),
      _ => $"[{x},{y}] {ValueAt(kind, x, y)} rays" + (AllRaysKnown ? "" : " (primary only: not a ray tracer)"),
    };
  }

  /// <summary>The map as a displayable image (values mapped to colours in [0, 1]).</summary>
  public FloatImage ToImage(MapKind kind)
  {
    var img = new FloatImage(Width, Height);
    Span<double> rgb = stackalloc double[3];
    (double min, double max) = Range(kind);
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
      {
        rgb.Clear();
        double v = kind == MapKind.NormalAbsolute ? 0.0 : ValueAt(kind, x, y);
        switch (kind)
        {
          case MapKind.Depth:
            // Near is bright, far dark, on a log scale (as GrCis shows depth).
            if (!double.IsInfinity(v) && max > 0.0)
            {
              double g = max > min ? 1.0 - Math.Log(1.0 + v - min) / Math.Log(1.0 + max - min) : 1.0;
              rgb[0] = rgb[1] = rgb[2] = 0.1 + 0.9 * g;
            }
            break;
          case MapKind.NormalAbsolute:
            Vector3d n = NormalAt(x, y);
            if (n != Vector3d.Zero)
            {
              rgb[0] = 0.5 * (n.X + 1.0);
              rgb[1] = 0.5 * (n.Y + 1.0);
              rgb[2] = 0.5 * (n.Z + 1.0);
            }
            break;
          case MapKind.NormalRelative:
            if (!double.IsNaN(v))
              HeatPalette.Color(v / 90.0, rgb);
            break;
          case MapKind.Noise:
            // No estimate stays black.
            if (!double.IsNaN(v))
              HeatPalette.Color(max > min ? (v - min) / (max - min) : 0.0, rgb);
            break;
          default:
            HeatPalette.Color(max > min ? (v - min) / (max - min) : 0.0, rgb);
            break;
        }
        img.SetPixel(x, y, rgb);
      }
    return img;
  }

  /// <summary>Smallest and largest finite value of a scalar map.</summary>
  public (double Min, double Max) Range(MapKind kind)
  {
    double min = double.PositiveInfinity, max = double.NegativeInfinity;
    if (kind == MapKind.NormalAbsolute)
      return (-1.0, 1.0);
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
      {
        double v = ValueAt(kind, x, y);
        if (double.IsFinite(v))
        {
          min = Math.Min(min, v);
          max = Math.Max(max, v);
        }
      }
    return min <= max ? (min, max) : (0.0, 0.0);
  }

  /// <summary>Saves the map image as PNG (atomically).</summary>
  public void SavePng(MapKind kind, string path) => PngFile.Save(path, ToImage(kind), 1.0);

  /// <summary>Saves the map's values as CSV (atomically; see <see cref="WriteCsv"/>).</summary>
  public void SaveCsv(MapKind kind, string path) => AtomicText.Write(path, w => WriteCsv(kind, w));

  /// <summary>Writes the map's values as CSV: <c>x,y,value</c> (or <c>x,y,nx,ny,nz</c> for absolute normals); no hit = empty.</summary>
  public void WriteCsv(MapKind kind, TextWriter w)
  {
    var c = CultureInfo.InvariantCulture;
    w.WriteLine(kind switch
    {
      MapKind.Depth => "x,y,depth",
      MapKind.NormalRelative => "x,y,angle_deg",
      MapKind.NormalAbsolute => "x,y,nx,ny,nz",
      MapKind.PrimaryRays => "x,y,primary_rays",
      MapKind.Noise => "x,y,standard_error",
      _ => "x,y,all_rays",
    });
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
      {
        w.Write(x.ToString(c));
        w.Write(',');
        w.Write(y.ToString(c));
        w.Write(',');
        if (kind == MapKind.NormalAbsolute)
        {
          Vector3d n = NormalAt(x, y);
          if (n != Vector3d.Zero)
            w.Write(string.Create(c, $"{n.X:R},{n.Y:R},{n.Z:R}"));
          else
            w.Write(",,");
        }
        else
        {
          double v = ValueAt(kind, x, y);
          if (double.IsFinite(v))
            w.Write(v.ToString("R", c));
        }
        w.WriteLine();
      }
  }

  /// <summary>Saves the point cloud as an ASCII PLY file (atomically; see <see cref="WritePointCloud"/>).</summary>
  public void SavePointCloud(string path, FloatImage? colors = null, double gamma = 1.0) =>
    AtomicText.Write(path, w => WritePointCloud(w, colors, gamma));

  /// <summary>
  /// Writes the primary hit points (one per pixel with a hit, averaged over its samples) as an ASCII PLY
  /// point cloud with normals, coloured from <paramref name="colors"/> (display gamma) when given.
  /// </summary>
  public void WritePointCloud(TextWriter w, FloatImage? colors = null, double gamma = 1.0)
  {
    Rgb8Image? rgb = colors != null && colors.Width == Width && colors.Height == Height && colors.Bands is 1 or 3
      ? Rgb8Image.FromFloatImage(colors, gamma) : null;
    int count = 0;
    foreach (int h in maps.Hits)
      if (h > 0)
        count++;
    var c = CultureInfo.InvariantCulture;
    w.WriteLine("ply");
    w.WriteLine("format ascii 1.0");
    w.WriteLine("comment GrCis primary hit points, one per pixel");
    w.WriteLine(string.Create(c, $"element vertex {count}"));
    foreach (string p in new[] { "x", "y", "z", "nx", "ny", "nz" })
      w.WriteLine($"property double {p}");
    if (rgb != null)
      foreach (string p in new[] { "red", "green", "blue" })
        w.WriteLine($"property uchar {p}");
    w.WriteLine("end_header");
    for (int y = 0; y < Height; y++)
      for (int x = 0; x < Width; x++)
      {
        if (HitPointAt(x, y) is not Vector3d p)
          continue;
        Vector3d n = NormalAt(x, y);
        w.Write(string.Create(c, $"{p.X:R} {p.Y:R} {p.Z:R} {n.X:R} {n.Y:R} {n.Z:R}"));
        if (rgb != null)
        {
          (byte r, byte g, byte b) = rgb.GetPixel(x, y);
          w.Write(string.Create(c, $" {r} {g} {b}"));
        }
        w.WriteLine();
      }
  }
}
