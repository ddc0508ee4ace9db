using System;
using System.Diagnostics;
using System.Linq;
using System.Runtime.Loader;
using Xunit.Abstractions;

namespace GrCis.Scripting.Tests;

[CollectionDefinition(nameof(MemoryCollection), DisableParallelization = true)]
public class MemoryCollection { }

/// <summary>Editing and re-running a script many times keeps memory bounded: old versions are unloaded.</summary>
[Collection(nameof(MemoryCollection))]
public class MemoryTests
{
  readonly ITestOutputHelper output;

  public MemoryTests(ITestOutputHelper output) => this.output = output;

  // A script of realistic size: a class, a method, a loop; each version differs in a constant.
  static string Version(int v) => $@"
// version {v}
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] {{ 1.0, 0.6, 0.1 }}, 0.1, 0.8, 0.2, {16 + v}));
scene.Intersectable = root;
for (int i = 0; i < 5; i++)
  root.InsertChild(Make(i), Matrix4d.Scale(0.5) * Matrix4d.CreateTranslation(i, 0, 0));
scene.Camera = new Cam{v}();
context[""version""] = {v};

ISceneNode Make(int i)
{{
  DefaultSceneNode n = new DefaultSceneNode();
  n.SetAttribute(PropertyName.COLOR, new double[] {{ 0.1 * i, 0.5, {v}.0 / 1000.0 }});
  return n;
}}

class Cam{v} : ICamera
{{
  public double AspectRatio {{ get; set; }} = 1.0;
  public double Width {{ get; set; }} = 100;
  public double Height {{ get; set; }} = 100;
  public bool GetRay(double x, double y, out Vector3d p0, out Vector3d p1)
  {{
    p0 = Vector3d.Zero;
    p1 = new Vector3d(x / Width - 0.5, y / Height - 0.5, 1.0);
    return true;
  }}
}}
";

  static int LiveScriptContexts() =>
    AssemblyLoadContext.All.Count(c => c.Name != null && c.Name.StartsWith("GrCisScript", StringComparison.Ordinal));

  static long FullCollect()
  {
    for (int i = 0; i < 4; i++)
    {
      GC.Collect();
      GC.WaitForPendingFinalizers();
    }
    return GC.GetTotalMemory(forceFullCollection: true);
  }

  [Fact]
  public void Two_hundred_edited_versions_keep_memory_bounded_and_old_code_unloaded()
  {
    const int capacity = 16;
    const int versions = 200;
    const int warmUp = 20;
    using var host = new ScriptHost(capacity);
    int contextsBefore = LiveScriptContexts();

    long heapAfterWarmUp = 0, wsAfterWarmUp = 0;
    var watch = Stopwatch.StartNew();
    for (int v = 0; v < versions; v++)
    {
      ScriptScene r = host.Run(host.CompileSource(Version(v), "Edited.cs"));
      Assert.Equal(v, r.Context["version"]);
      if (v == warmUp - 1)
      {
        heapAfterWarmUp = FullCollect();
        wsAfterWarmUp = Process.GetCurrentProcess().WorkingSet64;
      }
    }
    watch.Stop();

    long heapAfter = FullCollect();
    long wsAfter = Process.GetCurrentProcess().WorkingSet64;
    int live = LiveScriptContexts() - contextsBefore;

    const double MiB = 1024.0 * 1024.0;
    output.WriteLine($"compiled {host.CompilationCount} versions in {watch.Elapsed.TotalSeconds:F1} s " +
                     $"({watch.Elapsed.TotalMilliseconds / versions:F0} ms each), cache capacity {capacity}");
    output.WriteLine($"managed heap after {warmUp}: {heapAfterWarmUp / MiB:F1} MiB, after {versions}: {heapAfter / MiB:F1} MiB " +
                     $"(growth {(heapAfter - heapAfterWarmUp) / MiB:F1} MiB)");
    output.WriteLine($"working set after {warmUp}: {wsAfterWarmUp / MiB:F1} MiB, after {versions}: {wsAfter / MiB:F1} MiB " +
                     $"(growth {(wsAfter - wsAfterWarmUp) / MiB:F1} MiB)");
    output.WriteLine($"script load contexts still alive: {live}");

    Assert.Equal(versions, host.CompilationCount);
    Assert.Equal(capacity, host.CachedScriptCount);
    // Evicted versions are really unloaded: only the cached ones (plus a few the GC has not finished) remain.
    Assert.InRange(live, 0, capacity + 8);
    // Generous bound on managed growth over 180 further versions (non-collectible loading grows without bound).
    Assert.InRange(heapAfter - heapAfterWarmUp, long.MinValue, 64L * 1024 * 1024);
  }
}
