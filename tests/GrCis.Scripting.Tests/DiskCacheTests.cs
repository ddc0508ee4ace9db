using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using GrCis.Scripting.Caching;
using Rendering;

namespace GrCis.Scripting.Tests;

/// <summary>
/// The compiled-script cache on disk: a script and its modules are compiled once per change, and what a later
/// process loads from the cache behaves as a fresh compilation (warnings, runtime error lines). Each test has a
/// cache folder of its own; a new host stands for a new process.
/// </summary>
public sealed class DiskCacheTests : IDisposable
{
  readonly ScratchFolder scratch = new("grcis-disk-cache-");

  public void Dispose() => scratch.Dispose();

  string CacheDir => Path.Combine(scratch.Path, "cache");

  ScriptCache NewCache(long maxBytes = ScriptCache.DefaultMaxBytes, int maxEntries = ScriptCache.DefaultMaxEntries) =>
    new(CacheDir, maxBytes, maxEntries);

  string[] Entries() =>
    Directory.Exists(CacheDir) ? Directory.GetFiles(CacheDir, "*" + ScriptCache.EntryExtension) : [];

  static string Versioned(int version) =>
    $"// version {version}\nscene.Intersectable = new Sphere();\ncontext[\"version\"] = {version};\n";

  [Fact]
  public void An_unchanged_script_is_loaded_from_the_cache_by_a_new_host_without_compiling()
  {
    string path = scratch.Write("Scene.cs", Versioned(1));
    using (var first = new ScriptHost(diskCache: NewCache()))
    {
      Assert.Equal(1, first.Load(path).Context["version"]);
      Assert.Equal(1, first.CompilationCount);
      Assert.Equal((0, 1, 1), (first.DiskCache!.Hits, first.DiskCache.Misses, first.DiskCache.Stores));
    }
    Assert.Single(Entries());

    ScriptCache cache = NewCache();
    using var second = new ScriptHost(diskCache: cache);
    ScriptScene run = second.Load(path);
    Assert.Equal(1, run.Context["version"]);
    Assert.IsType<Sphere>(run.Scene.Intersectable);
    Assert.Equal(0, second.CompilationCount);
    Assert.Equal((1, 0, 0), (cache.Hits, cache.Misses, cache.Stores));
  }

  [Fact]
  public void A_checked_draft_reports_its_diagnostics_and_is_not_written_to_the_disk_cache_but_a_run_of_it_reuses_it()
  {
    string path = scratch.Write("Scene.cs", Versioned(1));
    using var host = new ScriptHost(diskCache: NewCache());
    ScriptDiagnostic error = Assert.Single(host.Check("// draft\nint n = \"many\";\n", path));
    Assert.Equal((2, "CS0029"), (error.Line, error.Id));
    Assert.Empty(host.Check(Versioned(2), path));
    Assert.Empty(Entries());
    Assert.Equal(1, host.CompilationCount);
    // Running the checked text uses the compilation of the check.
    Assert.Equal(2, host.Run(host.CompileSource(Versioned(2), path)).Context["version"]);
    Assert.Equal(1, host.CompilationCount);
  }

  [Fact]
  public void An_edited_script_is_compiled_again_and_the_old_version_stays_cached()
  {
    string path = scratch.Write("Scene.cs", Versioned(1));
    using (var first = new ScriptHost(diskCache: NewCache()))
      first.Load(path);

    File.WriteAllText(path, Versioned(2));
    using (var second = new ScriptHost(diskCache: NewCache()))
    {
      Assert.Equal(2, second.Load(path).Context["version"]);
      Assert.Equal(1, second.CompilationCount);
    }

    File.WriteAllText(path, Versioned(1));
    using var third = new ScriptHost(diskCache: NewCache());
    Assert.Equal(1, third.Load(path).Context["version"]);
    Assert.Equal(0, third.CompilationCount);
    Assert.Equal(2, Entries().Length);
  }

  [Fact]
  public void An_edited_module_file_recompiles_the_module_and_the_script_that_uses_it()
  {
    string module = Path.Combine(scratch.Path, "mod");
    string helper = scratch.Write("mod/Numbers.cs", "namespace Mod { public static class Numbers { public static int Answer() => 41; } }\n");
    scratch.Write("mod/More.cs", "namespace Mod { public static class More { public static int One => 1; } }\n");
    string script = scratch.Write("Scene.cs", "scene.Intersectable = new Sphere();\ncontext[\"n\"] = Mod.Numbers.Answer() + Mod.More.One;\n");

    int Run(out ScriptHost host)
    {
      host = new ScriptHost(diskCache: NewCache());
      host.AddModule(module);
      return (int)host.Load(script).Context["n"];
    }

    Assert.Equal(42, Run(out ScriptHost h1));
    Assert.Equal((1, 1), (h1.ModuleCompilationCount, h1.CompilationCount));
    h1.Dispose();

    Assert.Equal(42, Run(out ScriptHost h2));
    Assert.Equal((0, 0), (h2.ModuleCompilationCount, h2.CompilationCount));
    Assert.Equal(2, h2.DiskCache!.Hits);
    h2.Dispose();

    File.WriteAllText(helper, "namespace Mod { public static class Numbers { public static int Answer() => 99; } }\n");
    Assert.Equal(100, Run(out ScriptHost h3));
    Assert.Equal((1, 1), (h3.ModuleCompilationCount, h3.CompilationCount));
    h3.Dispose();
  }

  [Fact]
  public void The_compile_hook_runs_before_each_compilation_and_never_for_a_cache_hit()
  {
    string module = Path.Combine(scratch.Path, "mod");
    scratch.Write("mod/Numbers.cs", "namespace Mod { public static class Numbers { public static int Answer() => 41; } }\n");
    string script = scratch.Write("Scene.cs", "scene.Intersectable = new Sphere();\ncontext[\"n\"] = Mod.Numbers.Answer();\n");

    (int Calls, int Compiled) Run()
    {
      int calls = 0;
      using var host = new ScriptHost(diskCache: NewCache()) { BeforeCompile = () => calls++ };
      host.AddModule(module);
      host.Load(script);
      host.Load(script);   // the memory cache's hit
      return (calls, host.ModuleCompilationCount + host.CompilationCount);
    }

    Assert.Equal((2, 2), Run());   // the module and the script compiled
    Assert.Equal((0, 0), Run());   // both from the disk cache
    File.AppendAllText(script, "// edited\n");
    Assert.Equal((1, 1), Run());   // the script again, the module from the cache
  }

  [Fact]
  public void Other_compiler_options_or_another_library_build_do_not_use_the_entry()
  {
    string path = scratch.Write("Scene.cs", Versioned(3));
    using (var debug = new ScriptHost(diskCache: NewCache()))
      debug.Load(path);
    using (var optimized = new ScriptHost(optimizeScripts: true, diskCache: NewCache()))
    {
      Assert.Equal(3, optimized.Load(path).Context["version"]);
      Assert.Equal(1, optimized.CompilationCount);
    }
    Assert.Equal(2, Entries().Length);

    // The library's identity is the MVIDs of the assemblies scripts compile against (deterministic builds:
    // they change exactly when an assembly does); a script key changes with it.
    foreach (Type t in new[] { typeof(OpenTK.Mathematics.Vector3d), typeof(IRayScene), typeof(Utilities.Util), typeof(ScriptHost), typeof(object) })
      Assert.Contains(t.Assembly.ManifestModule.ModuleVersionId.ToString(), CacheKeys.Library);
    string source = File.ReadAllText(path);
    Assert.NotEqual(CacheKeys.Script("library A", path, source, [], false), CacheKeys.Script("library B", path, source, [], false));
    Assert.Equal(CacheKeys.Script(path, source, [], false), CacheKeys.Script(CacheKeys.Library, path, source, [], false));
  }

  [Theory]
  [InlineData("truncated")]
  [InlineData("flipped byte")]
  [InlineData("empty")]
  [InlineData("another entry")]
  public void A_damaged_entry_is_ignored_and_replaced(string damage)
  {
    string path = scratch.Write("Scene.cs", Versioned(5));
    string other = scratch.Write("Other.cs", Versioned(6));
    using (var first = new ScriptHost(diskCache: NewCache()))
    {
      first.Load(other);
      first.Load(path);
    }
    // The entry's file name is its key.
    string entry = Path.Combine(CacheDir, CacheKeys.Script(path, File.ReadAllText(path), [], false) + ScriptCache.EntryExtension);
    Assert.True(File.Exists(entry));
    byte[] bytes = File.ReadAllBytes(entry);
    byte[] damaged = damage switch
    {
      "truncated" => bytes[..(bytes.Length / 2)],
      "flipped byte" => Flip(bytes, bytes.Length / 2),
      "empty" => [],
      _ => File.ReadAllBytes(Entries().Single(e => e != entry)),
    };
    File.WriteAllBytes(entry, damaged);

    ScriptCache cache = NewCache();
    using (var second = new ScriptHost(diskCache: cache))
    {
      Assert.Equal(5, second.Load(path).Context["version"]);
      Assert.Equal(1, second.CompilationCount);
      Assert.Equal((1, 1, 1), (cache.Rejected, cache.Misses, cache.Stores));
    }
    // Replaced by a fresh entry (not byte-equal to the first: the assembly's name carries the process's compile serial).
    byte[] replaced = File.ReadAllBytes(entry);
    Assert.NotEmpty(replaced);
    Assert.NotEqual(damaged, replaced);

    using var third = new ScriptHost(diskCache: NewCache());
    Assert.Equal(5, third.Load(path).Context["version"]);
    Assert.Equal(0, third.CompilationCount);
  }

  static byte[] Flip(byte[] bytes, int at)
  {
    byte[] copy = (byte[])bytes.Clone();
    copy[at] ^= 0x40;
    return copy;
  }

  [Fact]
  public void Warnings_and_runtime_error_lines_are_the_same_from_the_cache_as_from_a_fresh_compilation()
  {
    string module = Path.Combine(scratch.Path, "mod");
    // GRCIS007: a module type with the full name of a library type.
    scratch.Write("mod/AnimatedCamera.cs", """
      using OpenTK.Mathematics;

      namespace Rendering
      {
        public class AnimatedCamera : StaticCamera
        {
          public AnimatedCamera () : base(new Vector3d(0, 0, -5), Vector3d.UnitZ, 40.0) { }
        }
      }
      """);
    // A runtime error in a module, in a loop (interruption points move the compiled columns).
    scratch.Write("mod/Thrower.cs", """
      namespace Mod
      {
        public static class Thrower
        {
          public static int Fail (int n) { int[] a = new int[1]; for (int i = 0; i <= n; i++) { a[i] = i; } return a[0]; }
        }
      }
      """);
    // GRCIS005 in the script: an override with the access of another GrCis year; GRCIS004: a using of a namespace gone.
    string script = scratch.Write("Scene.cs", """
      using System.Windows.Forms;
      class OldTracer : RayTracing
      {
        protected override long shade (int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color) =>
          base.shade(depth, importance, ref p0, ref p1, color);
      }
      scene.Camera = new AnimatedCamera();
      context[PropertyName.CTX_ALGORITHM] = new OldTracer();
      if (param == "module") Mod.Thrower.Fail(3);
      for (int i = 0; i < 3; i++) { int[] b = new int[2]; if (param == "script") b[i] = i; }
      scene.Intersectable = new Sphere();
      """);

    (string[] Warnings, string Module, ScriptRuntimeException InScript, ScriptRuntimeException InModule) Observe(ScriptHost host)
    {
      ScriptModule m = host.AddModule(module);
      CompiledScript s = host.Compile(script);
      host.Run(s, "");
      var inScript = Assert.Throws<ScriptRuntimeException>(() => host.Run(s, "script"));
      var inModule = Assert.Throws<ScriptRuntimeException>(() => host.Run(s, "module"));
      return (s.Warnings.Select(w => w.ToString()).ToArray(), string.Join("\n", m.Warnings), inScript, inModule);
    }

    using var fresh = new ScriptHost(diskCache: NewCache());
    var a = Observe(fresh);
    Assert.Equal((1, 1), (fresh.CompilationCount, fresh.ModuleCompilationCount));
    using var cached = new ScriptHost(diskCache: NewCache());
    var b = Observe(cached);
    Assert.Equal((0, 0), (cached.CompilationCount, cached.ModuleCompilationCount));

    Assert.Contains(a.Warnings, w => w.Contains(ScriptDiagnostic.OverrideAccessId));
    Assert.Contains(a.Warnings, w => w.Contains(ScriptDiagnostic.MissingNamespaceId));
    Assert.Contains(ScriptDiagnostic.ShadowedLibraryTypeId, a.Module);
    Assert.Equal(a.Warnings, b.Warnings);
    Assert.Equal(a.Module, b.Module);

    Assert.Equal((script, 10), (a.InScript.Path, a.InScript.Line));
    Assert.Equal(File.ReadAllLines(script)[9].IndexOf("b[i]", StringComparison.Ordinal) + 1, a.InScript.Column);
    Assert.Equal((Path.Combine(module, "Thrower.cs"), 5), (a.InModule.Path, a.InModule.Line));
    Assert.Equal(File.ReadAllLines(Path.Combine(module, "Thrower.cs"))[4].IndexOf("a[i]", StringComparison.Ordinal) + 1, a.InModule.Column);
    Assert.Equal(a.InScript.Message, b.InScript.Message);
    Assert.Equal(a.InModule.Message, b.InModule.Message);
  }

  [Fact]
  public void Hosts_compiling_the_same_script_at_once_all_succeed_and_leave_one_whole_entry()
  {
    string path = scratch.Write("Scene.cs", Versioned(7));
    var hosts = Enumerable.Range(0, 4).Select(_ => new ScriptHost(diskCache: NewCache())).ToArray();
    try
    {
      var results = new int[hosts.Length];
      Parallel.For(0, hosts.Length, new ParallelOptions { MaxDegreeOfParallelism = hosts.Length },
        i => results[i] = (int)hosts[i].Load(path).Context["version"]);
      Assert.All(results, r => Assert.Equal(7, r));
    }
    finally
    {
      foreach (ScriptHost h in hosts)
        h.Dispose();
    }
    Assert.Single(Entries());
    Assert.Empty(Directory.GetFiles(CacheDir, "*.tmp"));
    using var later = new ScriptHost(diskCache: NewCache());
    later.Load(path);
    Assert.Equal(0, later.CompilationCount);
  }

  [Fact]
  public void The_folder_keeps_at_most_its_bound_of_entries_dropping_the_least_recently_used()
  {
    var paths = Enumerable.Range(0, 3).Select(i => scratch.Write($"S{i}.cs", Versioned(10 + i))).ToArray();
    var entryOf = new Dictionary<int, string>();
    using (var host = new ScriptHost(diskCache: NewCache(maxEntries: 2)))
      for (int i = 0; i < paths.Length; i++)
      {
        string[] before = Entries();
        host.Load(paths[i]);
        entryOf[i] = Entries().Except(before).Single();
        // An age for each entry, so the order does not hang on the file system's clock resolution.
        File.SetLastWriteTimeUtc(entryOf[i], DateTime.UtcNow.AddHours(i - 3));
      }
    // Written third, the newest entry was kept and the oldest one deleted.
    Assert.Equal(new[] { entryOf[1], entryOf[2] }.Order(), Entries().Order());

    // A hit marks an entry used: entry 1 is now newer than entry 2, so the next store drops entry 2.
    using (var host = new ScriptHost(diskCache: NewCache(maxEntries: 2)))
    {
      host.Load(paths[1]);
      Assert.Equal(0, host.CompilationCount);
      host.Load(paths[0]);
    }
    Assert.Equal(new[] { entryOf[0], entryOf[1] }.Order(), Entries().Order());
  }

  [Fact]
  public void An_entry_larger_than_the_size_bound_is_not_kept_and_the_script_still_runs()
  {
    string path = scratch.Write("Scene.cs", Versioned(8));
    using var host = new ScriptHost(diskCache: NewCache(maxBytes: 1024));
    Assert.Equal(8, host.Load(path).Context["version"]);
    Assert.Empty(Entries());
  }

  [Fact]
  public void A_cache_folder_that_cannot_be_written_only_costs_the_compilation()
  {
    string path = scratch.Write("Scene.cs", Versioned(9));
    // A file where the folder should be: no entry can be written.
    File.WriteAllText(CacheDir, "not a folder");
    using var host = new ScriptHost(diskCache: NewCache());
    Assert.Equal(9, host.Load(path).Context["version"]);
    Assert.Equal((1, 0), (host.DiskCache!.Misses, host.DiskCache.Stores));
  }

  [Fact]
  public void Clear_deletes_every_entry()
  {
    using (var host = new ScriptHost(diskCache: NewCache()))
      host.Load(scratch.Write("Scene.cs", Versioned(4)));
    Assert.Single(Entries());
    NewCache().Clear();
    Assert.Empty(Entries());
  }

  [SkippableFact]
  public void The_default_folder_is_the_variable_or_the_platform_cache_folder()
  {
    Assert.Equal(Path.GetFullPath("/tmp/mine"),
      ScriptCache.DefaultDirectory(v => v == ScriptCache.DirectoryVariable ? "/tmp/mine" : null));
    Skip.IfNot(OperatingSystem.IsLinux(), "the XDG rules are Linux's");
    Assert.Equal("/x/cache/grcis/scripts", ScriptCache.DefaultDirectory(v => v == "XDG_CACHE_HOME" ? "/x/cache" : null));
    string home = Environment.GetFolderPath(Environment.SpecialFolder.UserProfile);
    Assert.Equal(Path.Combine(home, ".cache", "grcis", "scripts"), ScriptCache.DefaultDirectory(_ => null));
    // A relative XDG_CACHE_HOME is ignored, as the XDG base directory rules say.
    Assert.Equal(Path.Combine(home, ".cache", "grcis", "scripts"), ScriptCache.DefaultDirectory(v => v == "XDG_CACHE_HOME" ? "rel" : null));
  }
}
