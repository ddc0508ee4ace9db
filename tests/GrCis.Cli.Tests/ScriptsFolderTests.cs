using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using GrCis.Cli.Jobs;
using GrCis.Cli.SceneSources;
using Rendering;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

/// <summary>
/// Every script in scripts/ compiles, runs and renders a non-flat image; each of the eleven classic
/// scripts renders bit-identically to the built-in scene of the same name (same size, settings, seed).
/// </summary>
public class ScriptsFolderTests
{
  const int Width = 80, Height = 60;

  /// <summary>Classic script file → built-in scene name.</summary>
  static readonly Dictionary<string, string> Classic = new()
  {
    ["FiveBalls.cs"] = "Five balls",
    ["HedgehogInTheCage.cs"] = "Hedgehog in the cage",
    ["Flags.cs"] = "Flags",
    ["SpherePlane.cs"] = "Sphere on the plane",
    ["TwoSpheres.cs"] = "Two spheres",
    ["SphereFlake.cs"] = "Sphere flake",
    ["Cubes.cs"] = "Cubes",
    ["Cylinders.cs"] = "Cylinders",
    ["Circus.cs"] = "Circus",
    ["Toroids.cs"] = "Toroids",
    ["Bezier.cs"] = "Bezier",
  };

  /// <summary>The other scripts, each showing a feature of the dialect or the library.</summary>
  static readonly string[] Features =
  {
    "Orbit.cs",          // animation: AnimatedRayScene, AnimatedCamera, PropertyAnimator, AnimatedNodeTransform
    "Optics.cs",         // glass: lens (CSG), cube, hollow ball
    "Panorama.cs",       // 360° camera class declared in the script
    "Glow.cs",           // SphereFront + RecursionFunction producing RayRecursion
    "TexturedTorus.cs",  // texture class declared in the script
    "MeshVase.cs",       // OBJ mesh shipped in scripts/data, found via CTX_SCRIPT_PATH
    "ImageTexture.cs",   // PNG shipped in scripts/data, a relative path found beside the script
    "Spiral.cs",         // parameters (strict), tooltip, size and supersampling from the script
    "GlossyReflections.cs", // DistributedRayTracing: glossy reflections by Phong exponent
    "SoftShadows.cs",    // DistributedRayTracing: SphereLightSource penumbrae
    "DepthOfField.cs",   // DistributedRayTracing: ThinLensCamera
    "CornellBox.cs",     // PathTracing: the benchmark's Cornell box, emissive rectangle
    "EmissiveSpheres.cs", // PathTracing: small emissive spheres, light-sampled by their cones
  };

  public static IEnumerable<object[]> ClassicCases()
  {
    foreach (var (file, name) in Classic)
      yield return new object[] { file, name, "" };
    // Parameters reach the script as they reach the built-in scene.
    yield return new object[] { "TwoSpheres.cs", "Two spheres", "n=1.3" };
    yield return new object[] { "Cubes.cs", "Cubes", "mat=glass, n=1.4" };
    yield return new object[] { "SphereFlake.cs", "Sphere flake", "depth=3, mat=mirror" };
  }

  public static IEnumerable<object[]> FeatureCases() => Features.Select(f => new object[] { f });

  [Fact]
  public void Every_script_in_the_folder_is_covered_by_a_test()
  {
    string[] files = Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal).ToArray()!;
    string[] covered = Classic.Keys.Concat(Features).OrderBy(f => f, StringComparer.Ordinal).ToArray();
    Assert.Equal(covered, files);
  }

  [Theory]
  [MemberData(nameof(ClassicCases))]
  public void Classic_script_renders_the_same_image_as_the_builtin_scene(string file, string builtInName, string param)
  {
    var settings = new RenderSettings { Width = Width, Height = Height, Threads = 2 };

    using var source = new ScriptSceneSource(RepoPaths.Script(file), param, Array.Empty<string>());
    PreparedRender setup = new RenderRequest(source, settings, GivenSettings.Size).Prepare();
    Assert.Empty(setup.Notes);
    FloatImage fromScript = setup.Render().Image;

    FloatImage builtIn = new RenderRequest(new BuiltInSceneSource(builtInName, param), settings).Prepare().Render().Image;

    AssertNotFlat(fromScript, file);
    int differing = 0;
    for (int i = 0; i < builtIn.Data.Length; i++)
      if (BitConverter.SingleToInt32Bits(builtIn.Data[i]) != BitConverter.SingleToInt32Bits(fromScript.Data[i]))
        differing++;
    Assert.True(differing == 0, $"{file} ({param}): {differing} of {builtIn.Data.Length} samples differ from the built-in '{builtInName}'");
  }

  [Theory]
  [MemberData(nameof(FeatureCases))]
  public void Feature_script_renders_a_non_flat_image(string file)
  {
    var settings = new RenderSettings { Width = Width, Height = Height, Threads = 2 };
    using var source = new ScriptSceneSource(RepoPaths.Script(file), "", Array.Empty<string>());
    PreparedRender setup = new RenderRequest(source, settings, GivenSettings.Size).Prepare();
    FloatImage image = setup.Render().Image;

    Assert.Equal(Width, image.Width);
    Assert.Equal(Height, image.Height);
    AssertNotFlat(image, file);
  }

  static void AssertNotFlat(FloatImage image, string what)
  {
    int distinct = image.Data.Distinct().Count();
    Assert.True(distinct > 20, $"{what}: the image is (nearly) constant ({distinct} distinct sample values)");
  }
}
