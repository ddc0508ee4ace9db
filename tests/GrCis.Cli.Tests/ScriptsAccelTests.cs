using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using GrCis.Cli.Jobs;
using GrCis.Cli.SceneSources;
using Rendering.Accel;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

/// <summary>
/// Every scene script in scripts/ renders the same bits through GrCis's faithful path (<c>--accel none</c>)
/// and the prepared fast path (script solids, CSG, meshes, SphereFront, custom cameras and textures included).
/// </summary>
public class ScriptsAccelTests
{
  const int Width = 48, Height = 36;

  public static IEnumerable<object[]> Scripts() =>
    Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal)
      .Select(f => new object[] { f! });

  static FloatImage Render(string file, AccelMode accel)
  {
    var settings = new RenderSettings { Width = Width, Height = Height, Threads = 2, Accel = accel };
    using var source = new ScriptSceneSource(RepoPaths.Script(file), "", Array.Empty<string>());
    PreparedRender setup = new RenderRequest(source, settings, GivenSettings.Size | GivenSettings.Accel).Prepare();
    return setup.Render().Image;
  }

  [Theory]
  [MemberData(nameof(Scripts))]
  public void Script_renders_identically_on_the_faithful_and_the_fast_path(string file)
  {
    FloatImage slow = Render(file, AccelMode.None);
    FloatImage fast = Render(file, AccelMode.Bvh);
    Assert.Equal(slow.Data.Length, fast.Data.Length);
    int differing = 0;
    for (int i = 0; i < slow.Data.Length; i++)
      if (BitConverter.SingleToInt32Bits(slow.Data[i]) != BitConverter.SingleToInt32Bits(fast.Data[i]))
        differing++;
    Assert.True(differing == 0, $"{file}: {differing} of {slow.Data.Length} samples differ between --accel none and bvh");
  }
}
