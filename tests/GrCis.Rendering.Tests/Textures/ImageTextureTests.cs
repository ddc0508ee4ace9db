using System;
using System.Collections.Generic;
using System.IO;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using StbImageWriteSharp;

namespace GrCis.Rendering.Tests.Textures;

/// <summary>
/// <see cref="ImageTexture"/>: texel lookup with each wrap mode, bilinear weights, the v axis pointing up the
/// image, bands, replace and multiply, files of every kind (floats above 1 kept), shared images, and rendered
/// scenes whose pixels show the texels.
/// </summary>
public sealed class ImageTextureTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-imagetexture-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  /// <summary>A one-band image from rows listed top row first.</summary>
  static FloatImage Gray(params float[][] rows)
  {
    var image = new FloatImage(rows[0].Length, rows.Length, 1);
    for (int y = 0; y < rows.Length; y++)
      for (int x = 0; x < rows[y].Length; x++)
        image[x, y, 0] = rows[y][x];
    return image;
  }

  static double At(ImageTexture t, double u, double v)
  {
    Span<double> c = stackalloc double[1];
    t.Sample(u, v, c);
    return c[0];
  }

  /// <summary>Four columns holding 0, 1, 2, 3.</summary>
  static ImageTexture Columns(TextureWrap wrap, bool bilinear = false) =>
    new(Gray(new float[] { 0, 1, 2, 3 })) { WrapU = wrap, Bilinear = bilinear };

  [Theory]
  // Texel centres inside [0, 1] read their own column in every mode.
  [InlineData(TextureWrap.Repeat, 0.125, 0)]
  [InlineData(TextureWrap.MirroredRepeat, 0.625, 2)]
  [InlineData(TextureWrap.Clamp, 0.875, 3)]
  // Past 1: the next tile starts again, comes back mirrored, or stays on the edge.
  [InlineData(TextureWrap.Repeat, 1.125, 0)]
  [InlineData(TextureWrap.MirroredRepeat, 1.125, 3)]
  [InlineData(TextureWrap.Clamp, 1.125, 3)]
  [InlineData(TextureWrap.Repeat, 1.625, 2)]
  [InlineData(TextureWrap.MirroredRepeat, 1.625, 1)]
  // Below 0.
  [InlineData(TextureWrap.Repeat, -0.125, 3)]
  [InlineData(TextureWrap.MirroredRepeat, -0.125, 0)]
  [InlineData(TextureWrap.Clamp, -0.125, 0)]
  [InlineData(TextureWrap.Repeat, -1.375, 2)]
  [InlineData(TextureWrap.MirroredRepeat, -1.375, 2)]
  [InlineData(TextureWrap.Clamp, -1.375, 0)]
  // Far out (an infinite plane near its horizon).
  [InlineData(TextureWrap.Repeat, 1.0e6 + 0.375, 1)]
  [InlineData(TextureWrap.MirroredRepeat, 1.0e6 + 1.375, 2)]
  [InlineData(TextureWrap.Clamp, -1.0e12, 0)]
  public void Nearest_texel_of_each_wrap_mode(TextureWrap wrap, double u, double expected) =>
    Assert.Equal(expected, At(Columns(wrap), u, 0.5));

  [Fact]
  public void Infinite_and_nan_coordinates_give_a_texel_not_nan()
  {
    foreach (TextureWrap wrap in Enum.GetValues<TextureWrap>())
      foreach (bool bilinear in new[] { false, true })
        foreach (double u in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity })
          Assert.InRange(At(Columns(wrap, bilinear), u, 0.5), 0.0, 3.0);
  }

  [Fact]
  public void Undefined_wrap_mode_is_refused()
  {
    var t = Columns(TextureWrap.Repeat);
    ArgumentOutOfRangeException e = Assert.Throws<ArgumentOutOfRangeException>(() => t.WrapV = (TextureWrap)7);
    Assert.Contains("Repeat, MirroredRepeat or Clamp", e.Message);
  }

  /// <summary>Top row 0, 0.25; bottom row 0.5, 1.</summary>
  static ImageTexture Square() => new(Gray(new float[] { 0.0f, 0.25f }, new float[] { 0.5f, 1.0f }));

  [Theory]
  // Texel centres: exactly the texel (v = 0.25 is the bottom row).
  [InlineData(0.25, 0.25, 0.5)]
  [InlineData(0.75, 0.25, 1.0)]
  [InlineData(0.25, 0.75, 0.0)]
  [InlineData(0.75, 0.75, 0.25)]
  // Midpoints between two centres: their mean; the middle of all four: the mean of four.
  [InlineData(0.5, 0.25, 0.75)]
  [InlineData(0.5, 0.75, 0.125)]
  [InlineData(0.25, 0.5, 0.25)]
  [InlineData(0.5, 0.5, 0.4375)]
  // A quarter of the way from the bottom-left centre to the bottom-right one.
  [InlineData(0.375, 0.25, 0.625)]
  public void Bilinear_is_exact_at_texel_centres_and_linear_between_them(double u, double v, double expected) =>
    Assert.Equal(expected, At(Square(), u, v));

  [Theory]
  // u = 0 lies half a texel left of the first centre: Repeat blends in the last column, the others stay on the first.
  [InlineData(TextureWrap.Repeat, 0.75)]
  [InlineData(TextureWrap.MirroredRepeat, 0.5)]
  [InlineData(TextureWrap.Clamp, 0.5)]
  public void Bilinear_at_the_edge_follows_the_wrap_mode(TextureWrap wrap, double expected)
  {
    ImageTexture t = Square();
    t.WrapU = wrap;
    Assert.Equal(expected, At(t, 0.0, 0.25));
  }

  [Fact]
  public void V_zero_is_the_bottom_row_and_v_one_the_top_row()
  {
    // Image row 0 (top) holds 1, row 1 (bottom) holds 0.
    var t = new ImageTexture(Gray(new float[] { 1 }, new float[] { 0 })) { Bilinear = false };
    Assert.Equal(0.0, At(t, 0.5, 0.25));
    Assert.Equal(1.0, At(t, 0.5, 0.75));
    t.WrapV = TextureWrap.Clamp;
    Assert.Equal(0.0, At(t, 0.5, 0.0));
    Assert.Equal(1.0, At(t, 0.5, 1.0));
  }

  [Fact]
  public void Scale_and_offset_move_the_coordinates_before_wrapping()
  {
    ImageTexture t = Columns(TextureWrap.Repeat);
    t.Fu = 2.0;
    t.OffsetU = 0.5;
    // 2 · 0.3125 + 0.5 = 1.125 → the first column of the next tile.
    Assert.Equal(0.0, At(t, 0.3125, 0.5));
    // 2 · 0.125 + 0.5 = 0.75 → column 3.
    Assert.Equal(3.0, At(t, 0.125, 0.5));
    t.Fv = -1.0; // flips v; one row, so nothing changes
    Assert.Equal(3.0, At(t, 0.125, 0.5));
  }

  [Fact]
  public void Bands_follow_the_surface_colour()
  {
    var rgb = new FloatImage(1, 1, 3);
    rgb.SetPixel(0, 0, new[] { 0.25, 0.5, 0.75 });
    var t = new ImageTexture(rgb);
    double[] one = new double[1], three = new double[3], four = new double[4];
    t.Sample(0.5, 0.5, one);
    t.Sample(0.5, 0.5, three);
    t.Sample(0.5, 0.5, four);
    Assert.Equal(new[] { 0.5 }, one);                        // the mean for a one-band surface
    Assert.Equal(new[] { 0.25, 0.5, 0.75 }, three);
    Assert.Equal(new[] { 0.25, 0.5, 0.75, 0.75 }, four);     // the last band repeated

    var gray = new ImageTexture(Gray(new float[] { 0.5f }));
    gray.Sample(0.5, 0.5, three);
    Assert.Equal(new[] { 0.5, 0.5, 0.5 }, three);
  }

  static Intersection Hit(double u, double v, params double[] surface) =>
    new() { TextureCoord = new Vector2d(u, v), SurfaceColor = surface };

  [Fact]
  public void Apply_replaces_the_surface_colour_with_a_new_array_on_a_plain_hit()
  {
    double[] shared = { 0.9, 0.9, 0.9 };
    Intersection hit = Hit(0.25, 0.25, shared);
    long hash = Square().Apply(hit);
    Assert.Equal(new[] { 0.5, 0.5, 0.5 }, hit.SurfaceColor);
    Assert.NotSame(shared, hit.SurfaceColor);
    Assert.Equal(new[] { 0.9, 0.9, 0.9 }, shared);   // someone else's array is never written
    Assert.True(hit.textureApplied);

    // Another texel, another hash (adaptive sampling refines there).
    Assert.NotEqual(hash, Square().Apply(Hit(0.75, 0.25, 0.9, 0.9, 0.9)));
  }

  [Fact]
  public void Multiply_scales_the_surface_colour_band_by_band()
  {
    var rgb = new FloatImage(1, 1, 3);
    rgb.SetPixel(0, 0, new[] { 0.5, 0.25, 1.0 });
    Intersection hit = Hit(0.5, 0.5, 0.5, 1.0, 2.0);
    new ImageTexture(rgb) { Multiply = true }.Apply(hit);
    Assert.Equal(new[] { 0.25, 0.25, 2.0 }, hit.SurfaceColor);
  }

  string WritePng(string name, int width, int height, byte[] rgb)
  {
    string path = Path.Combine(dir, name);
    using (FileStream s = File.Create(path))
      new ImageWriter().WritePng(rgb, width, height, ColorComponents.RedGreenBlue, s);
    return path;
  }

  [Fact]
  public void Png_bytes_become_their_value_over_255_or_with_a_gamma_its_power()
  {
    string path = WritePng("c.png", 1, 1, new byte[] { 200, 100, 50 });
    double[] c = new double[3];
    new ImageTexture(path).Sample(0.5, 0.5, c);
    Assert.Equal(new double[] { (float)(200 / 255.0), (float)(100 / 255.0), (float)(50 / 255.0) }, c);
    new ImageTexture(path, gamma: 2.2).Sample(0.5, 0.5, c);
    Assert.Equal((float)Math.Pow(200 / 255.0, 2.2), c[0]);
  }

  [Fact]
  public void Pfm_and_hdr_files_keep_values_above_one()
  {
    var bright = new FloatImage(1, 1, 3);
    bright.SetPixel(0, 0, new[] { 4.0, 0.5, 12.25 });
    string pfm = Path.Combine(dir, "bright.pfm");
    PfmWriter.Save(pfm, bright);
    double[] c = new double[3];
    new ImageTexture(pfm, gamma: 2.2).Sample(0.5, 0.5, c);   // gamma is for 8-bit files only
    Assert.Equal(new[] { 4.0, 0.5, 12.25 }, c);

    // Flat RGBE (mantissas m, shared exponent e: m · 2^(e − 136)): (4, 0.5, 0.25).
    string hdr = Path.Combine(dir, "bright.hdr");
    using (FileStream s = File.Create(hdr))
    {
      s.Write("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n"u8);
      s.Write(new byte[] { 128, 16, 8, 131 });
    }
    new ImageTexture(hdr).Sample(0.5, 0.5, c);
    Assert.Equal(new[] { 4.0, 0.5, 0.25 }, c);
  }

  [Fact]
  public void Missing_file_error_names_the_path()
  {
    string path = Path.Combine(dir, "no-such-texture.png");
    FileNotFoundException e = Assert.Throws<FileNotFoundException>(() => new ImageTexture(path));
    Assert.Contains(path, e.Message);
  }

  [Fact]
  public void Missing_relative_file_error_names_it_and_the_script_folder()
  {
    using (global::Utilities.DataFiles.UseScriptDirectory(dir))
    {
      FileNotFoundException e = Assert.Throws<FileNotFoundException>(() => new ImageTexture("data/nope.png"));
      Assert.Contains("'data/nope.png'", e.Message);
      Assert.Contains("beside the script in " + dir, e.Message);
      Assert.Equal("data/nope.png", e.FileName);
    }
  }

  [Fact]
  public void Corrupt_file_error_starts_with_the_path()
  {
    string path = Path.Combine(dir, "broken.png");
    File.WriteAllBytes(path, new byte[] { 0x89, (byte)'P', (byte)'N', (byte)'G', 1, 2, 3 });
    InvalidDataException e = Assert.Throws<InvalidDataException>(() => new ImageTexture(path));
    Assert.StartsWith(path + ": ", e.Message);
  }

  [Fact]
  public void A_relative_path_is_found_beside_the_running_script()
  {
    Directory.CreateDirectory(Path.Combine(dir, "data"));
    string full = WritePng(Path.Combine("data", "tex.png"), 1, 1, new byte[] { 255, 0, 0 });
    using (global::Utilities.DataFiles.UseScriptDirectory(dir))
    {
      var t = new ImageTexture("data\\tex.png"); // written on Windows
      Assert.Equal(Path.GetFullPath(full), Path.GetFullPath(t.FileName!));
    }
  }

  [Fact]
  public void Textures_of_one_file_share_its_pixels_and_an_edited_file_is_read_again()
  {
    string path = WritePng("shared.png", 2, 1, new byte[] { 10, 20, 30, 40, 50, 60 });
    var a = new ImageTexture(path);
    var b = new ImageTexture(path);
    Assert.Same(a.Image, b.Image);
    Assert.NotSame(a.Image, new ImageTexture(path, gamma: 2.2).Image);

    WritePng("shared.png", 3, 1, new byte[] { 1, 2, 3, 4, 5, 6, 7, 8, 9 });
    var c = new ImageTexture(path);
    Assert.Equal(3, c.Image.Width);
    Assert.Equal(2, a.Image.Width);
  }

  /// <summary>A texture that animates its offset: cloned per render thread, as GrCis clones time-dependent parts.</summary>
  sealed class ScrollingTexture : ImageTexture, ITimeDependent
  {
    public ScrollingTexture(FloatImage image) : base(image) { }

    public double Start { get; set; }
    public double End { get; set; } = 1.0;

    public double Time
    {
      get => OffsetU;
      set => OffsetU = value;
    }

    public object Clone() => MemberwiseClone();
  }

  [Fact]
  public void Cloning_for_a_render_thread_shares_the_pixels()
  {
    var still = new ImageTexture(Gray(new float[] { 1, 2 }));
    var scrolling = new ScrollingTexture(still.Image);

    // An animated node clones its time-dependent attribute...
    var node = new AnimatedCSGInnerNode(SetOperation.Union);
    node.SetAttribute(PropertyName.TEXTURE, scrolling);
    var copy = (ImageTexture)((AnimatedCSGInnerNode)node.Clone()).GetLocalAttribute(PropertyName.TEXTURE)!;
    Assert.NotSame(scrolling, copy);
    Assert.Same(still.Image, copy.Image);   // ...without its pixels

    // GrCis's clone helper: still textures of a list are shared as they are, animated ones cloned.
    var source = new CSGInnerNode(SetOperation.Union);
    source.SetAttribute(PropertyName.TEXTURE, new List<ITexture> { still, scrolling });
    var target = new CSGInnerNode(SetOperation.Union);
    source.ShareCloneAttributes(target);
    var textures = new List<ITexture>(target.GetTextures()!);
    Assert.Same(still, textures[0]);
    Assert.NotSame(scrolling, textures[1]);
    Assert.Same(still.Image, ((ImageTexture)textures[1]).Image);
  }

  // ------------------------------------------------------------------ rendered

  /// <summary>A plane rectangle [−1, 1]² facing the camera (texture coordinates [0, 1]², u right, v up), the texture on it.</summary>
  static DefaultRayScene Board(ITexture? texture, double[]? color = null, bool lit = false)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.2, 0.6, 0.3, 16));
    var board = new Plane(-1.0, 1.0, -1.0, 1.0);
    if (texture != null)
      board.SetAttribute(PropertyName.TEXTURE, texture);
    if (color != null)
      board.SetAttribute(PropertyName.COLOR, color);
    root.InsertChild(board, Matrix4d.Identity);
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.0, 0.0 },
      Camera = new StaticCamera(new Vector3d(0.0, 0.0, -3.0), Vector3d.UnitZ, 50.0),
      Sources = lit
        ? new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.5), new PointLightSource(new Vector3d(-2, 3, -4), 1.0) })
        : new LinkedList<ILightSource>(),
    };
  }

  static double[] Pixel(FloatImage image, int x, int y) => image.GetPixel(x, y);

  [Fact]
  public void A_rendered_board_shows_the_image_upright_and_unmirrored()
  {
    // Top-left red, top-right green, bottom-left blue, bottom-right white.
    string path = WritePng("quadrants.png", 2, 2, new byte[] { 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255 });
    var texture = new ImageTexture(path) { Bilinear = false };
    foreach (AccelMode accel in new[] { AccelMode.None, AccelMode.Bvh })
    {
      // Ray casting without lights: a pixel is the surface colour itself.
      FloatImage image = RenderHelper.Render(Board(texture), accel, 40, 40, rayCasting: true);
      Assert.Equal(new[] { 1.0, 0.0, 0.0 }, Pixel(image, 14, 14));
      Assert.Equal(new[] { 0.0, 1.0, 0.0 }, Pixel(image, 25, 14));
      Assert.Equal(new[] { 0.0, 0.0, 1.0 }, Pixel(image, 14, 25));
      Assert.Equal(new[] { 1.0, 1.0, 1.0 }, Pixel(image, 25, 25));
      Assert.Equal(new[] { 0.0, 0.0, 0.0 }, Pixel(image, 1, 1));   // beside the board: background
    }
  }

  [Fact]
  public void A_png_texel_renders_exactly_like_the_colour_attribute_of_its_value()
  {
    // What a GrCis user expects: a texture painted in colour c looks as COLOR = c / 255 does (both then get the output gamma).
    string path = WritePng("flat.png", 1, 1, new byte[] { 200, 100, 50 });
    double[] color = { (float)(200 / 255.0), (float)(100 / 255.0), (float)(50 / 255.0) };
    FloatImage textured = RenderHelper.Render(Board(new ImageTexture(path), lit: true), AccelMode.Bvh, 32, 32);
    FloatImage plain = RenderHelper.Render(Board(null, color, lit: true), AccelMode.Bvh, 32, 32);
    Assert.Equal(plain.Data, textured.Data);
  }

  /// <summary>An image-textured sphere (replace), cube (multiply, mirrored) and infinite floor (nearest), lit.</summary>
  internal static DefaultRayScene TexturedSolids(FloatImage image)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.8, 0.8, 0.8 }, 0.2, 0.6, 0.3, 16));
    var ball = new Sphere();
    ball.SetAttribute(PropertyName.TEXTURE, new ImageTexture(image) { Fu = 3.0, Fv = 2.0 });
    root.InsertChild(ball, Matrix4d.RotateX(-Math.PI / 2) * Matrix4d.CreateTranslation(-1.2, 0.0, 0.0));
    var box = new Cube();
    box.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.6, 1.0 });
    box.SetAttribute(PropertyName.TEXTURE, new ImageTexture(image) { Multiply = true, WrapU = TextureWrap.MirroredRepeat, Fu = 2.0 });
    root.InsertChild(box, Matrix4d.RotateY(0.6) * Matrix4d.CreateTranslation(0.8, -0.5, 0.0));
    var floor = new Plane();
    floor.SetAttribute(PropertyName.TEXTURE, new ImageTexture(image) { Bilinear = false, Fu = 0.5, Fv = 0.5 });
    root.InsertChild(floor, Matrix4d.RotateX(-Math.PI / 2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.05, 0.1 },
      Camera = new StaticCamera(new Vector3d(0.0, 1.0, -6.0), new Vector3d(0.0, -0.2, 1.0), 50.0),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.6), new PointLightSource(new Vector3d(-3, 4, -4), 1.0) }),
    };
  }

  internal static FloatImage Pattern()
  {
    var image = new FloatImage(8, 8);
    for (int y = 0; y < 8; y++)
      for (int x = 0; x < 8; x++)
        image.SetPixel(x, y, new[] { x / 7.0, y / 7.0, (x + y) % 2 });
    return image;
  }

  [Fact]
  public void Textured_sphere_cube_and_plane_render_the_same_bits_on_the_faithful_and_the_fast_path()
  {
    FloatImage slow = RenderHelper.Render(TexturedSolids(Pattern()), AccelMode.None, 64, 48, threads: 2);
    FloatImage fast = RenderHelper.Render(TexturedSolids(Pattern()), AccelMode.Bvh, 64, 48, threads: 2);
    Assert.Equal(slow.Data, fast.Data);
    Assert.True(new HashSet<float>(fast.Data).Count > 100, "the textures should vary the image");
  }

  [Fact]
  public void A_lean_hit_on_an_image_textured_sphere_carries_the_texture_coordinates_of_a_full_one()
  {
    PreparedScene p = PreparedScene.Prepare(TexturedSolids(Pattern()).Intersectable);
    var p0 = new Vector3d(-1.2, 0.3, -6.0);
    var p1 = new Vector3d(0.0, 0.0, 1.0);
    Intersection full = p.FirstHit(p0, p1, new Intersection(), surfaceOnly: false)!;
    Intersection lean = p.FirstHit(p0, p1, new Intersection(), surfaceOnly: true)!;
    Assert.IsType<Sphere>(lean.Solid);
    Assert.NotEqual(default, lean.TextureCoord);
    Assert.Equal(full.TextureCoord, lean.TextureCoord);
    Assert.Equal(0, p.FallbackCount);
  }

  /// <summary>A script's image texture that also reads the tangent (which a lean completion leaves out).</summary>
  sealed class TangentShadedTexture : ImageTexture
  {
    public TangentShadedTexture(FloatImage image) : base(image) { }

    public override long Apply(Intersection inter)
    {
      long h = base.Apply(inter);
      inter.SurfaceColor![0] = 0.5 + 0.5 * inter.TangentU.Normalized().X;
      return h;
    }
  }

  [Fact]
  public void A_subclass_overriding_apply_gets_complete_hits()
  {
    DefaultRayScene Scene()
    {
      DefaultRayScene scene = TexturedSolids(Pattern());
      var ball = new Sphere();
      ball.SetAttribute(PropertyName.TEXTURE, new TangentShadedTexture(Pattern()));
      ((CSGInnerNode)scene.Intersectable!).InsertChild(ball, Matrix4d.CreateScale(0.6) * Matrix4d.CreateTranslation(0.0, 1.2, 0.0));
      return scene;
    }
    FloatImage slow = RenderHelper.Render(Scene(), AccelMode.None, 64, 48);
    FloatImage fast = RenderHelper.Render(Scene(), AccelMode.Bvh, 64, 48);
    Assert.Equal(slow.Data, fast.Data);
  }
}
