using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// Classic-style scripts that use the library's solids, cameras, lights, textures, image functions
/// and <see cref="Scenes"/> helpers: they compile, run, build the expected scene and render it.
/// (Until the library classes were merged these were "pending" scripts that could only fail for
/// the missing classes.)
/// </summary>
public class ClassicStyleScriptTests
{
  static string Classic(string name) => Path.Combine(TestData.Root, "classic", name);

  static FloatImage Render(IRayScene scene, IImageFunction? function = null, int width = 64, int height = 48)
  {
    var renderer = new SimpleImageSynthesizer { Width = width, Height = height };
    return TileRenderer.Render(scene, function ?? new RayTracing(scene), renderer, new RenderOptions { Threads = 2 });
  }

  [Fact]
  public void FiveBalls_classic_scene()
  {
    using var host = new ScriptHost();
    ScriptScene r = host.Run(host.Compile(Classic("FiveBalls.cs")));

    var root = Assert.IsType<CSGInnerNode>(r.Scene.Intersectable);
    Assert.Equal(5, root.Children.Count);
    Assert.IsType<StaticCamera>(r.Scene.Camera);
    Assert.Equal(2, r.Scene.Sources!.Count);
    Assert.IsType<RayTracing>(r.Algorithm);

    // The middle ball is the unit sphere at the origin: the axis ray from z = -10 meets it at t = 9.
    LinkedList<Intersection>? hits = root.Intersect(new Vector3d(0, 0, -10), new Vector3d(0, 0, 1));
    Assert.NotNull(hits);
    Assert.Equal(9.0, hits!.First!.Value.T, 9);
  }

  [Fact]
  public void FiveBalls_script_renders_like_the_builtin_scene()
  {
    using var host = new ScriptHost();
    ScriptScene r = host.Run(host.Compile(Classic("FiveBalls.cs")));

    FloatImage fromScript = Render(r.Scene, r.Algorithm);
    FloatImage builtIn = Render(Scenes.Create("Five balls"));

    // Same spheres, inserted in another order: the image does not depend on the order.
    Assert.True(fromScript.Data.Distinct().Count() > 10, "the render should not be flat");
    Assert.Equal(builtIn.Data, fromScript.Data);
  }

  [Fact]
  public void SphereFlake_with_Scenes_flake_parameters_and_preprocessing()
  {
    using var host = new ScriptHost();
    ScriptScene r = host.Run(host.Compile(Classic("SphereFlake.cs")), "depth=2, mat=glass, n=1.5");
    Assert.True(r.Preprocessed);
    Assert.Equal(true, r.Context["flakePreprocessed"]);
    Assert.Equal(640, r.Width);
    Assert.Equal(480, r.Height);
    Assert.StartsWith("depth=<int>", r.ToolTip);
    Assert.IsType<RayTracing>(r.Algorithm);
    Assert.IsType<DefaultBackground>(r.Scene.Background);

    var root = Assert.IsType<CSGInnerNode>(r.Scene.Intersectable);
    Assert.Equal(2, root.Children.Count);
    ISceneNode flake = root.Children.First();
    var pm = Assert.IsType<PhongMaterial>(flake.GetLocalAttribute(PropertyName.MATERIAL));
    Assert.Equal(1.5, pm.n);
    Assert.Equal(0.9, pm.Kt);
    // depth 2: the centre sphere plus seven sub-flakes of one sphere each.
    Assert.Equal(8, flake.Children.Count);

    FloatImage image = Render(r.Scene, r.Algorithm, 48, 36);
    Assert.True(image.Data.Distinct().Count() > 10, "the render should not be flat");
  }

  [Fact]
  public void CheckerTexture_subclass_declared_after_use()
  {
    using var host = new ScriptHost();
    ScriptScene r = host.Run(host.Compile(Classic("StripedChecker.cs")));
    ISceneNode sphere = Assert.Single(((CSGInnerNode)r.Scene.Intersectable!).Children);
    var texture = (ITexture)sphere.GetLocalAttribute(PropertyName.TEXTURE)!;
    Assert.Equal("Stripes", texture.GetType().Name);
    Assert.Equal(typeof(CheckerTexture), texture.GetType().BaseType);

    var hit = new Intersection { TextureCoord = new Vector2d(0.15, 0.5), SurfaceColor = new[] { 0.0, 0.0, 0.0 } };
    texture.Apply(hit);
    Assert.Equal(new[] { 1.0, 1.0, 0.0 }, hit.SurfaceColor);

    // Rendered (ambient light only), the stripes show: yellowish and bluish pixels on the sphere.
    FloatImage image = Render(r.Scene);
    bool yellow = false, blue = false;
    for (int y = 0; y < image.Height; y++)
      for (int x = 0; x < image.Width; x++)
      {
        float red = image[x, y, 0], b = image[x, y, 2];
        yellow |= red > 0.05f && red > 3.0f * b;
        blue |= b > 0.05f && b > 3.0f * red;
      }
    Assert.True(yellow && blue, "both stripe colours should be visible");
  }
}
