using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Threading.Tasks;
using GrCis.Scripting;
using GrCis.Scripting.Caching;

namespace GrCis.Cli.Tests;

/// <summary>
/// The compiled-script cache holds code grcis runs, so it trusts only what the user alone could have put there: a
/// folder of another user's or one others may write is not used (one warning saying why); an entry that is a link or a
/// FIFO is a miss, not a hang or an abort; an entry not signed with the user's secret (a plain hash anyone can
/// recompute, the former scheme) is never loaded.
/// </summary>
public class ScriptCacheTrustTests
{
  static string Versioned(int version) =>
    $"// version {version}\nscene.Intersectable = new Rendering.Sphere();\ncontext[\"version\"] = {version};\n";

  static string[] Entries(string cacheDir) => Directory.GetFiles(cacheDir, "*" + ScriptCache.EntryExtension);

  /// <summary>Loads <paramref name="script"/> through a host with <paramref name="cache"/> (a new process, as far as the cache knows); at most a minute.</summary>
  static int LoadVersion(string script, ScriptCache cache)
  {
    Task<int> load = Task.Run(() =>
    {
      using var host = new ScriptHost(diskCache: cache);
      return (int)host.Load(script).Context["version"];
    });
    Assert.True(load.Wait(TimeSpan.FromMinutes(1)), "loading the script hung");
    return load.Result;
  }

  static void Run(string file, params string[] args)
  {
    using Process p = Process.Start(file, args)!;
    p.WaitForExit();
    Assert.Equal(0, p.ExitCode);
  }

  [UnixFact]
  public void A_folder_others_may_write_is_not_used_and_grcis_says_so_once()
  {
    using var dir = new TempDirectory();
    string cacheDir = dir.File("shared");
    Directory.CreateDirectory(cacheDir);
    File.SetUnixFileMode(cacheDir, (UnixFileMode)0b111_111_111);   // 777
    File.WriteAllText(dir.File("ball.cs"), StuckScriptsCamera + Versioned(1));
    var env = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cacheDir };

    (int code, string output, string error) = GrcisProcess.Run(dir.Path, env, "render", "ball.cs", "-s", "8x6", "-o", "out.png", "-q");
    Assert.True(code == 0, error);
    string warning = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries));
    Assert.Equal($"grcis: warning: the compiled-script cache '{cacheDir}' is not used: other users may write it (mode 777, writable by its group and others); " +
                 "make it yours alone (chmod 700) or set GRCIS_CACHE_DIR to another folder; scripts are compiled afresh", warning);
    Assert.Empty(Directory.GetFiles(cacheDir));
  }

  const string StuckScriptsCamera = "scene.Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 60.0);\n" +
                                    "scene.Sources = new LinkedList<ILightSource>();\n";

  [UnixFact]
  public void A_group_writable_folder_or_another_users_is_refused_and_a_planted_entry_is_never_read()
  {
    using var dir = new TempDirectory();
    string script = dir.File("Scene.cs");
    File.WriteAllText(script, Versioned(1));
    string good = dir.File("good");
    Assert.Equal(1, LoadVersion(script, new ScriptCache(good)));
    string entry = Assert.Single(Entries(good));

    string group = dir.File("group");
    Directory.CreateDirectory(group);
    File.SetUnixFileMode(group, (UnixFileMode)0b111_111_101);   // 775
    // Another user's folder: one made for uid 4242 when the tests run as root, else one of root's.
    string other = "/usr/share";
    if (Environment.UserName == "root")
    {
      other = dir.File("other");
      Directory.CreateDirectory(other);
      Run("chown", "4242", other);
    }
    foreach ((string folder, string why) in new[] { (group, "writable by its group"), (other, "belongs to another user") })
    {
      if (folder != other)
        File.Copy(entry, Path.Combine(folder, Path.GetFileName(entry)));
      var warnings = new StringWriter();
      var cache = new ScriptCache(folder, warnings: warnings);
      Assert.Equal(1, LoadVersion(script, cache));
      Assert.Contains(why, cache.Refused);
      Assert.Contains($"'{folder}' is not used", warnings.ToString());
      Assert.Equal((0, 0), (cache.Hits, cache.Stores));
    }
  }

  [UnixFact]
  public void An_entry_that_is_a_fifo_or_a_link_is_a_miss_and_is_replaced()
  {
    using var dir = new TempDirectory();
    string script = dir.File("Scene.cs");
    File.WriteAllText(script, Versioned(1));
    string cacheDir = dir.File("cache");
    Assert.Equal(1, LoadVersion(script, new ScriptCache(cacheDir)));
    string entry = Assert.Single(Entries(cacheDir));
    string copy = dir.File("copy" + ScriptCache.EntryExtension);
    File.Copy(entry, copy);

    foreach (string plant in new[] { "fifo", "/dev/zero", copy })
    {
      File.Delete(entry);
      if (plant == "fifo")
        Run("mkfifo", entry);
      else
        File.CreateSymbolicLink(entry, plant);
      var cache = new ScriptCache(cacheDir);
      Assert.Equal(1, LoadVersion(script, cache));
      Assert.Equal((0, 1, 1, 1), (cache.Hits, cache.Misses, cache.Rejected, cache.Stores));
      Assert.Null(new FileInfo(entry).LinkTarget);   // replaced by a regular file
    }
  }

  [UnixFact]
  public void An_entry_forged_with_a_recomputed_hash_of_the_former_scheme_is_refused()
  {
    using var dir = new TempDirectory();
    string a = dir.File("A.cs"), b = dir.File("B.cs");
    File.WriteAllText(a, Versioned(1));
    File.WriteAllText(b, Versioned(2));
    string cacheDir = dir.File("cache");
    Assert.Equal(1, LoadVersion(a, new ScriptCache(cacheDir)));
    string entryA = Assert.Single(Entries(cacheDir));
    Assert.Equal(2, LoadVersion(b, new ScriptCache(cacheDir)));
    string entryB = Entries(cacheDir).Single(e => e != entryA);

    // B's code under A's key, with the trailing SHA-256 of the whole entry recomputed: what the former check accepted.
    string keyA = Path.GetFileNameWithoutExtension(entryA), keyB = Path.GetFileNameWithoutExtension(entryB);
    byte[] forged = File.ReadAllBytes(entryB);
    int at = forged.AsSpan().IndexOf(Encoding.UTF8.GetBytes(keyB));
    Assert.True(at > 0);
    Encoding.UTF8.GetBytes(keyA).CopyTo(forged, at);
    SHA256.HashData(forged.AsSpan(0, forged.Length - 32)).CopyTo(forged, forged.Length - 32);
    File.WriteAllBytes(entryA, forged);

    var cache = new ScriptCache(cacheDir);
    Assert.Equal(1, LoadVersion(a, cache));
    Assert.Equal((0, 1, 1), (cache.Hits, cache.Rejected, cache.Stores));
  }

  [UnixFact]
  public void A_secret_others_may_read_makes_the_cache_unused()
  {
    using var dir = new TempDirectory();
    string script = dir.File("Scene.cs");
    File.WriteAllText(script, Versioned(1));
    string cacheDir = dir.File("cache");
    Assert.Equal(1, LoadVersion(script, new ScriptCache(cacheDir)));
    string key = Path.Combine(cacheDir, ScriptCache.KeyFileName);
    Assert.Equal(UnixFileMode.UserRead | UnixFileMode.UserWrite, File.GetUnixFileMode(key));
    File.SetUnixFileMode(key, (UnixFileMode)0b110_100_100);   // 644

    var cache = new ScriptCache(cacheDir, warnings: new StringWriter());
    Assert.Equal(1, LoadVersion(script, cache));
    Assert.Contains("may be read or written by others", cache.Refused);
    Assert.Equal(0, cache.Hits);
  }
}
