using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Distributed;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The Whitted kernel's plain-surface path (balls and planes, Phong, checkers, point and ambient lights, hits kept as
/// records): the scenes it serves, what turns it off, and the same bits and hashes as <see cref="RayTracing.shade"/>
/// under every setting it reads.
/// </summary>
public class PlainSurfaceKernelTests
{
  sealed class OwnLight(Vector3d position, double intensity) : PointLightSource(position, intensity);

  sealed class OwnChecker(double fu, double fv, double[] color2) : CheckerTexture(fu, fv, color2);

  static DefaultRayScene Scene(string name)
  {
    var scene = (DefaultRayScene)Scenes.Create(name);
    scene.Camera!.Width = 40;
    scene.Camera.Height = 30;
    return scene;
  }

  /// <summary>Whether <paramref name="function"/>'s kernel shades its scene on the plain path (bound on this thread).</summary>
  static bool TakesPlainPath(RayTracing function)
  {
    function.Prepare();
    WhittedKernel kernel = WhittedKernel.For(function)!;
    kernel.Sample(20.5, 15.5, new double[3]);
    return ShadingScratch.Current.Bound!.Plain != null;
  }

  [Fact]
  public void Scenes_of_library_balls_and_planes_take_the_plain_path_and_others_do_not()
  {
    var plain = new List<string>();
    foreach (string name in Scenes.Names)
    {
      DefaultRayScene scene = Scene(name);
      var function = new RayTracing(scene);
      bool takes = TakesPlainPath(function);
      // Plain surfaces lit only by the library's point and ambient lights.
      bool expected = function.LastPrepared!.PlainSurfaces &&
                      (scene.Sources ?? []).All(l => l.GetType() == typeof(PointLightSource) || l.GetType() == typeof(AmbientLightSource));
      Assert.True(takes == expected, $"{name}: plain path {takes}, expected {expected}");
      if (takes)
        plain.Add(name);
    }
    // The scenes of balls, planes and cubes; the others have cylinders, CSG, tori, Bézier patches or (Test scene) an area light.
    Assert.Equal(["Five balls", "Sphere on the plane", "Two spheres", "Sphere flake", "Cubes"], plain);
  }

  [Fact]
  public void What_the_plain_path_cannot_serve_turns_it_off()
  {
    Assert.True(TakesPlainPath(new RayTracing(Scene("Two spheres"))));

    // A subclass's own mirror direction (the plain path has no hit to hand it).
    DefaultRayScene mirrored = Scene("Two spheres");
    Assert.False(TakesPlainPath(new WhittedKernelTests.WiderMirror { Scene = mirrored }));
    // A light of a script's class.
    DefaultRayScene lit = Scene("Two spheres");
    lit.Sources!.Add(new OwnLight(new Vector3d(3.0, 5.0, -4.0), 0.5));
    Assert.False(TakesPlainPath(new RayTracing(lit)));
    // A texture of a script's class.
    DefaultRayScene textured = Scene("Two spheres");
    ((CSGInnerNode)textured.Intersectable!).Children.Last().SetAttribute(PropertyName.TEXTURE, new OwnChecker(1.0, 1.0, [0.0, 0.0, 1.0]));
    Assert.False(TakesPlainPath(new RayTracing(textured)));
    // The faithful path.
    Assert.Null(WhittedKernel.For(new RayTracing(Scene("Two spheres")) { Accel = AccelMode.None }));
    // Distributed ray tracing samples its own directions.
    Assert.False(TakesPlainPath(new DistributedRayTracing(Scene("Two spheres"))));
  }

  /// <summary>
  /// The settings the plain path reads, one changed at a time (and none), on Two spheres; the other plain scenes as they
  /// are, and Cubes with a checker on a cube (its face's texture coordinates).
  /// </summary>
  public static IEnumerable<object[]> Variants() =>
    new[] { "default", "fresnel", "transparent shadows", "no shadows", "no reflections", "no refractions", "no lights",
            "two-band colour", "two checkers", "shallow" }.Select(v => new object[] { "Two spheres", v })
    .Concat(new[] { "Five balls", "Sphere on the plane", "Sphere flake", "Cubes" }.Select(n => new object[] { n, "default" }))
    .Append(["Cubes", "two checkers"]);

  static void Apply(string variant, DefaultRayScene scene, params RayTracing[] functions)
  {
    var root = (CSGInnerNode)scene.Intersectable!;
    foreach (RayTracing function in functions)
      switch (variant)
      {
        case "fresnel": function.FresnelRefraction = true; break;
        case "transparent shadows": function.TransparentShadows = true; break;
        case "no shadows": function.DoShadows = false; break;
        case "no reflections": function.DoReflections = false; break;
        case "no refractions": function.DoRefractions = false; break;
        case "shallow": function.MaxLevel = 1; break;
      }
    switch (variant)
    {
      case "no lights": scene.Sources = new LinkedList<ILightSource>(); break;
      case "two-band colour":
        // The glass ball's colour has two bands where the image has three: the short paths of the band loops.
        root.Children.First().SetAttribute(PropertyName.COLOR, new[] { 0.5, 0.2 });
        break;
      case "two checkers":
        // A second checker with two bands over the last child's colour (Two spheres: the floor's checker; Cubes: a cube's
        // own colour): the surface colour changes length between them.
        ((DefaultSceneNode)root.Children.Last()).AddTexture(new CheckerTexture(2.0, 1.5, [0.2, 0.9]));
        break;
    }
  }

  [Theory]
  [MemberData(nameof(Variants))]
  public void Plain_path_gives_shades_colours_rays_and_hashes(string name, string variant)
  {
    // One scene for both: a hit's hash is its solid's object hash.
    DefaultRayScene scene = Scene(name);
    var function = new RayTracing(scene);
    var textbook = new WhittedKernelTests.TextbookRayTracing(scene);
    Apply(variant, scene, function, textbook);
    Assert.True(TakesPlainPath(function), $"{name}, {variant}: the plain path was not taken");
    WhittedKernel kernel = WhittedKernel.For(function)!;
    var k = new double[3];
    var t = new double[3];
    var hashes = new HashSet<long>();
    ShadingScratch scratch = ShadingScratch.Current;
    for (int y = 0; y < 30; y++)
      for (int x = 0; x < 40; x++)
      {
        long before = scratch.Rays, hitsBefore = scratch.Hits;
        long hash = kernel.Sample(x + 0.25, y + 0.75, k);
        long rays = scratch.Rays - before, hits = scratch.Hits - hitsBefore;
        before = scratch.Rays;
        hitsBefore = scratch.Hits;
        Assert.Equal(textbook.GetSample(x + 0.25, y + 0.75, t), hash);
        Assert.Equal(scratch.Rays - before, rays);
        Assert.Equal(scratch.Hits - hitsBefore, hits);
        for (int c = 0; c < 3; c++)
          Assert.True(BitConverter.DoubleToInt64Bits(t[c]) == BitConverter.DoubleToInt64Bits(k[c]),
                      $"{name}, {variant}, pixel ({x}, {y}), band {c}: kernel {k[c]:R}, shade {t[c]:R}");
        hashes.Add(hash);
      }
    Assert.True(hashes.Count > 10, $"{name}, {variant}: {hashes.Count} distinct hashes");
  }
}
