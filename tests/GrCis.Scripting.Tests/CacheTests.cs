using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Rendering;

namespace GrCis.Scripting.Tests;

/// <summary>A script compiles once per (path, content, modules); runs reuse the compiled code.</summary>
public class CacheTests
{
  static string Versioned(int version) =>
    $"// version {version}\nscene.BackgroundColor = new double[] {{ {version}.0, 0.0, 0.0 }};\ncontext[\"version\"] = {version};\n";

  [Fact]
  public void Running_a_script_many_times_compiles_it_once()
  {
    using var host = new ScriptHost();
    string path = TestData.Script("ClassesAndMethods.cs");
    for (int frame = 0; frame < 10; frame++)
      Assert.NotNull(host.Load(path, $"frame={frame}").Scene.Camera);

    Assert.Equal(1, host.CompilationCount);
    Assert.Same(host.Compile(path), host.Compile(path));
    Assert.Equal(1, host.CompilationCount);
  }

  [Fact]
  public void Running_on_many_threads_compiles_once_and_gives_each_thread_its_own_scene()
  {
    using var host = new ScriptHost();
    string path = TestData.Script("ClassesAndMethods.cs");
    var scenes = new IRayScene[16];
    Parallel.For(0, scenes.Length, new ParallelOptions { MaxDegreeOfParallelism = 8 }, i =>
    {
      scenes[i] = host.Load(path).Scene;
    });

    Assert.Equal(1, host.CompilationCount);
    Assert.Equal(scenes.Length, scenes.Distinct().Count());
    Assert.All(scenes, s => Assert.Equal(3, ((CSGInnerNode)s.Intersectable!).Children.Count));
  }

  [Fact]
  public void Edited_script_content_is_recompiled_and_unchanged_content_is_not()
  {
    using var host = new ScriptHost();
    string path = Path.Combine(Path.GetTempPath(), $"grcis-cache-{System.Guid.NewGuid():N}.cs");
    try
    {
      File.WriteAllText(path, Versioned(1));
      Assert.Equal(1, host.Load(path).Context["version"]);
      File.WriteAllText(path, Versioned(2));
      Assert.Equal(2, host.Load(path).Context["version"]);
      File.WriteAllText(path, Versioned(1));
      Assert.Equal(1, host.Load(path).Context["version"]);
      Assert.Equal(2, host.CompilationCount);
    }
    finally
    {
      File.Delete(path);
    }
  }

  [Fact]
  public void Same_content_at_another_path_is_a_separate_entry_so_messages_name_the_right_file()
  {
    using var host = new ScriptHost();
    CompiledScript a = host.CompileSource(Versioned(1), "a.cs");
    CompiledScript b = host.CompileSource(Versioned(1), "b.cs");
    Assert.NotSame(a, b);
    Assert.EndsWith("b.cs", b.Path);
    Assert.Equal(2, host.CompilationCount);
  }

  [Fact]
  public void Cache_is_bounded_and_evicts_the_least_recently_used_script()
  {
    using var host = new ScriptHost(cacheCapacity: 3);
    CompiledScript v0 = host.CompileSource(Versioned(0), "v.cs");
    host.CompileSource(Versioned(1), "v.cs");
    host.CompileSource(Versioned(2), "v.cs");
    host.CompileSource(Versioned(0), "v.cs");       // touch v0: v1 is now the oldest
    host.CompileSource(Versioned(3), "v.cs");       // evicts v1
    Assert.Equal(3, host.CachedScriptCount);
    Assert.Equal(4, host.CompilationCount);

    Assert.Same(v0, host.CompileSource(Versioned(0), "v.cs"));
    Assert.Equal(4, host.CompilationCount);
    host.CompileSource(Versioned(1), "v.cs");       // was evicted: compiles again
    Assert.Equal(5, host.CompilationCount);
  }

  [Fact]
  public void A_script_held_by_the_caller_still_runs_after_eviction()
  {
    using var host = new ScriptHost(cacheCapacity: 1);
    CompiledScript held = host.CompileSource(Versioned(7), "held.cs");
    host.CompileSource(Versioned(8), "other.cs");   // evicts and unloads 'held'
    Assert.Equal(1, host.CachedScriptCount);

    var ctx = new Dictionary<string, object>();
    ScriptScene r = host.Run(held, context: ctx);
    Assert.Equal(7, r.Context["version"]);
    Assert.Equal(new[] { 7.0, 0.0, 0.0 }, r.Scene.BackgroundColor);
  }

  [Fact]
  public void Cache_capacity_must_be_positive()
  {
    Assert.Throws<System.ArgumentOutOfRangeException>(() => new ScriptHost(cacheCapacity: 0));
  }
}
