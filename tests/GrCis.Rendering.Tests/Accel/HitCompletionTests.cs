using System;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// Surface completion (plain spheres, planes and cubes shaded only by the library) computes just what the library's
/// shading reads, with the same bits; anything a script could read keeps the full completion.
/// </summary>
public class HitCompletionTests
{
  static DefaultRayScene Scene(params ILightSource[] lights)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    var plain = new Sphere();
    plain.SetAttribute(PropertyName.COLOR, new[] { 1.0, 0.6, 0.0 });
    root.InsertChild(plain, Matrix4d.Scale(1.0, 1.5, 0.7) * Matrix4d.CreateTranslation(-1.5, 0, 0));
    var checkered = new Sphere();
    checkered.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(20.0, 10.0, new[] { 1.0, 0.8, 0.2 }));
    root.InsertChild(checkered, Matrix4d.RotateY(0.4) * Matrix4d.CreateTranslation(1.5, 0.2, 0));
    var box = new Cube();
    box.SetAttribute(PropertyName.COLOR, new[] { 0.2, 0.4, 1.0 });
    root.InsertChild(box, Matrix4d.Scale(0.8, 0.5, 0.6) * Matrix4d.RotateY(0.7) * Matrix4d.CreateTranslation(-0.4, -0.9, -2.5));
    var checkeredBox = new Cube();
    checkeredBox.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(4.0, 4.0, new[] { 0.1, 0.9, 0.3 }));
    root.InsertChild(checkeredBox, Matrix4d.RotateX(0.3) * Matrix4d.CreateTranslation(0.6, 1.6, -3.0));
    var floor = new Plane(-3.0, 3.0, -2.0, 4.0);
    floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(2.0, 2.0, new[] { 1.0, 1.0, 1.0 }));
    root.InsertChild(floor, Matrix4d.RotateX(-Math.PI / 2) * Matrix4d.CreateTranslation(0, -1, 0));
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(new Vector3d(0, 1, -8), new Vector3d(0, -0.1, 1), 50),
      Sources = new LinkedList<ILightSource>(lights.Length > 0 ? lights : new ILightSource[] { new AmbientLightSource(0.8), new PointLightSource(new Vector3d(-5, 3, -3), 1.0) }),
    };
  }

  [Fact]
  public void Surface_completed_hits_have_the_same_point_normal_colour_and_read_texture_coordinates_as_full_ones()
  {
    PreparedScene ps = PreparedScene.Prepare(Scene().Intersectable);
    var r = new Random(5);
    int hits = 0, untextured = 0, cubes = 0;
    for (int n = 0; n < 20_000; n++)
    {
      var p0 = new Vector3d(r.NextDouble() * 8 - 4, r.NextDouble() * 4 - 1, -8 + r.NextDouble() * 12);
      var p1 = new Vector3d(r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1, r.NextDouble() * 2 - 1);
      long fallbacks = ps.FallbackCount;
      Intersection? full = ps.FirstHit(p0, p1, new Intersection(), surfaceOnly: false);
      Intersection? lean = ps.FirstHit(p0, p1, new Intersection(), surfaceOnly: true);
      Assert.Equal(full == null, lean == null);
      // A fallback's hit comes from a list and is not completed here: it would prove nothing.
      if (full == null || lean == null || ps.FallbackCount != fallbacks)
        continue;
      hits++;
      long hf = ApplyTextures(full), hl = ApplyTextures(lean);
      Assert.Equal(hf, hl);
      Assert.Equal(full.T, lean.T);
      Assert.Equal(full.CoordWorld, lean.CoordWorld);
      Assert.Equal(full.Normal, lean.Normal);
      Assert.Equal(full.NormalLocal, lean.NormalLocal);
      Assert.Equal(full.SurfaceColor, lean.SurfaceColor);
      Assert.Same(full.Material, lean.Material);
      cubes += full.Solid is Cube ? 1 : 0;
      if (full.Textures != null || full.Solid is Cube)
        Assert.Equal(full.TextureCoord, lean.TextureCoord);
      else
      {
        // The plain sphere's texture coordinates are what the lean completion leaves out.
        untextured++;
        Assert.Equal(default, lean.TextureCoord);
        Assert.True(full.TextureCoord != default, $"{full.Solid?.GetType().Name} at {full.CoordLocal}, textures {full.Textures?.Count}");
      }
    }
    Assert.True(hits > 2_000 && untextured > 200 && cubes > 200, $"{hits} hits, {untextured} on the plain sphere, {cubes} on cubes");
  }

  static long ApplyTextures(Intersection i)
  {
    long h = 0;
    if (i.Textures != null)
      foreach (ITexture t in i.Textures)
        h = h * 11 + t.Apply(i);
    return h;
  }

  /// <summary>A script-style light that reads the hit's texture coordinates.</summary>
  sealed class TextureCoordLight : PointLightSource
  {
    public TextureCoordLight() : base(new Vector3d(-5, 3, -3), 1.0) { }

    public override double[]? GetIntensity(Intersection intersection, out Vector3d dir)
    {
      double[]? i = base.GetIntensity(intersection, out dir);
      return i == null ? null : new[] { intersection.TextureCoord.X, intersection.TextureCoord.Y, 1.0 };
    }
  }

  /// <summary>A ray tracer subclass (as in a script) that shades by texture coordinates.</summary>
  sealed class TextureCoordTracing : RayTracing
  {
    public TextureCoordTracing(IRayScene sc) : base(sc) { }

    public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
    {
      long h = base.shade(depth, importance, ref p0, ref p1, color);
      Intersection? i = FirstHitAt(depth + 100, p0, p1);
      if (i != null)
      {
        CompleteAndTexture(i);
        color[0] += i.TextureCoord.X;
        color[1] += i.TextureCoord.Y;
        color[2] += i.TangentU.X;
      }
      return h;
    }
  }

  [Fact]
  public void A_light_of_a_script_sees_the_texture_coordinates_of_plain_spheres()
  {
    FloatImage slow = RenderHelper.Render(Scene(new TextureCoordLight()), AccelMode.None, 64, 48);
    FloatImage fast = RenderHelper.Render(Scene(new TextureCoordLight()), AccelMode.Bvh, 64, 48);
    Assert.Equal(0, Differences(slow, fast));
  }

  [Fact]
  public void A_ray_tracer_subclass_sees_complete_hits()
  {
    FloatImage Render(AccelMode mode)
    {
      DefaultRayScene scene = Scene();
      var f = new TextureCoordTracing(scene) { Accel = mode };
      var renderer = new SimpleImageSynthesizer { Width = 64, Height = 48 };
      return global::Rendering.Execution.TileRenderer.Render(scene, f, renderer, new global::Rendering.Execution.RenderOptions { Threads = 1 });
    }
    Assert.Equal(0, Differences(Render(AccelMode.None), Render(AccelMode.Bvh)));
  }

  static int Differences(FloatImage a, FloatImage b)
  {
    int d = 0;
    for (int y = 0; y < a.Height; y++)
      for (int x = 0; x < a.Width; x++)
      {
        double[] pa = a.GetPixel(x, y), pb = b.GetPixel(x, y);
        for (int c = 0; c < pa.Length; c++)
          if (pa[c] != pb[c])
          {
            d++;
            break;
          }
      }
    return d;
  }
}
