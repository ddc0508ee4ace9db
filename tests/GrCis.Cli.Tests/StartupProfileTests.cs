using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using GrCis.Scripting.Caching;

namespace GrCis.Cli.Tests;

public class StartupProfileTests
{
  [Theory]
  [InlineData(true, "render", "fiveballs", "-o", "a.png")]
  [InlineData(true, "animate", "Five balls")]
  [InlineData(true, "bench")]
  [InlineData(true, "list")]
  [InlineData(false, "render", "scene.cs")]
  [InlineData(true, "render", "fiveballs", "-o", "scene.cs.png")]
  [InlineData(false, "render", "fiveballs", "--no-cache")]
  [InlineData(false, "animate", "Anim.CS")]
  [InlineData(false, "studio")]
  [InlineData(false, "init", "folder")]
  [InlineData(false, "--help")]
  [InlineData(false, "rendr", "fiveballs")]
  [InlineData(false)]
  public void Commands_get_a_profile_unless_they_run_a_script_or_skip_the_cache(bool expected, params string[] args)
  {
    Assert.Equal(expected, StartupProfile.Applies(args));
  }

  [Theory]
  [InlineData(true, "render", "scene.cs", "-o", "a.png")]
  [InlineData(true, "animate", "Anim.CS")]
  [InlineData(true, "info", "scene.cs")]
  [InlineData(false, "render", "fiveballs")]
  [InlineData(false, "render", "scene.cs", "--no-cache")]
  [InlineData(false, "studio", "scene.cs")]
  [InlineData(false, "export", "scene.cs")]
  [InlineData(false)]
  public void Script_runs_of_profiled_commands_start_a_profile_when_they_compile(bool expected, params string[] args)
  {
    Assert.Equal(expected, StartupProfile.CompileHook(args) != null);
  }

  [Theory]
  [InlineData("studio", "studio")]
  [InlineData("studio", "studio", "scripts", "--port", "8800")]
  [InlineData("studio-server", "studio", "scripts", "--host", "127.0.0.1", "--no-open", "--public-port", "8800")]
  [InlineData(null, "render", "fiveballs")]
  [InlineData(null)]
  public void The_studio_s_supervisor_and_its_studio_process_have_profiles_of_their_own(string? expected, params string[] args)
  {
    Assert.Equal(expected, StartupProfile.StudioProfile(args));
  }

  [Fact]
  public void Profile_is_named_by_the_command_and_the_build()
  {
    Assert.Equal("render-0123abcd" + StartupProfile.Extension, StartupProfile.FileName("render", "0123abcd"));
  }

  [Fact]
  public void Build_id_is_sixteen_hex_digits_and_stable_within_a_build()
  {
    string id = StartupProfile.BuildId();
    Assert.Matches("^[0-9a-f]{16}$", id);
    Assert.Equal(id, StartupProfile.BuildId());
  }

  [Fact]
  public void Pruning_keeps_the_most_recently_written_profiles_and_other_files()
  {
    using var dir = new TempDirectory();
    DateTime now = DateTime.UtcNow;
    for (int i = 0; i < 20; i++)
    {
      string f = dir.File($"render-{i:x16}{StartupProfile.Extension}");
      File.WriteAllText(f, "x");
      File.SetLastWriteTimeUtc(f, now.AddMinutes(-i));
    }
    File.WriteAllText(dir.File("other.txt"), "kept");
    File.SetLastWriteTimeUtc(dir.File("other.txt"), now.AddDays(-1));

    StartupProfile.Prune(dir.Path, StartupProfile.Kept);

    string[] left = Directory.GetFiles(dir.Path, "*" + StartupProfile.Extension).Select(Path.GetFileName).Order().ToArray()!;
    Assert.Equal(Enumerable.Range(0, StartupProfile.Kept).Select(i => $"render-{i:x16}{StartupProfile.Extension}").Order(), left);
    Assert.True(File.Exists(dir.File("other.txt")));
  }

  [Fact]
  public void A_run_records_its_command_s_profile_in_the_cache_folder_and_the_next_one_rewrites_it()
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    var env = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache };
    for (int run = 0; run < 2; run++)
    {
      var r = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, env, "render", "fiveballs", "--size", "16x12", "-q", "-o", "a.png"));
      Assert.True(r.Code == 0, r.Error);
      string[] profiles = Directory.GetFiles(Path.Combine(cache, "startup"), "*" + StartupProfile.Extension);
      Assert.Single(profiles);
      Assert.StartsWith("render-", Path.GetFileName(profiles[0]));
      Assert.True(new FileInfo(profiles[0]).Length > 0);
    }
  }

  [Fact]
  public void A_run_that_adds_a_profile_leaves_the_newest_ones_up_to_the_limit()
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    string startup = Directory.CreateDirectory(Path.Combine(cache, "startup")).FullName;
    if (!OperatingSystem.IsWindows())
    {
      File.SetUnixFileMode(cache, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
      File.SetUnixFileMode(startup, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
    }
    DateTime now = DateTime.UtcNow;
    for (int i = 0; i < StartupProfile.Kept + 4; i++)
    {
      string f = Path.Combine(startup, StartupProfile.FileName("bench", $"{i:x16}"));
      File.WriteAllText(f, "x");
      File.SetLastWriteTimeUtc(f, now.AddMinutes(-1 - i));
    }

    var r = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache },
                                                   "render", "fiveballs", "--size", "16x12", "-q", "-o", "a.png"));

    Assert.True(r.Code == 0, r.Error);
    string[] left = Directory.GetFiles(startup, "*" + StartupProfile.Extension).Select(Path.GetFileName).Order().ToArray()!;
    string[] expected = [StartupProfile.FileName("render", StartupProfile.BuildId()),
                         .. Enumerable.Range(0, StartupProfile.Kept - 1).Select(i => StartupProfile.FileName("bench", $"{i:x16}"))];
    Assert.Equal(expected.Order(), left);
  }

  [Fact]
  public void Only_a_run_that_compiles_its_script_records_the_compile_profile_and_a_cached_run_its_own()
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    string startup = Path.Combine(cache, "startup");
    var env = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache };
    File.WriteAllText(dir.File("s.cs"), "scene.Intersectable = new Sphere();\n");
    string[] render = ["render", "s.cs", "--size", "16x12", "-q", "-o", "a.png"];

    var compiled = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, env, render));
    Assert.True(compiled.Code == 0, compiled.Error);
    string profile = Path.Combine(startup, StartupProfile.FileName("render" + StartupProfile.CompileSuffix, StartupProfile.BuildId()));
    string script = Path.Combine(startup, StartupProfile.FileName("render" + StartupProfile.ScriptSuffix, StartupProfile.BuildId()));
    Assert.Equal([profile, script], Directory.GetFiles(startup).Order());
    Assert.True(new FileInfo(profile).Length > 0);

    // The next run finds the script compiled: it records its own profile, and the compiler's stays as it was.
    File.SetLastWriteTimeUtc(profile, DateTime.UtcNow.AddHours(-1));
    File.SetLastWriteTimeUtc(script, DateTime.UtcNow.AddHours(-1));
    byte[] before = File.ReadAllBytes(profile);
    var cached = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, env, render));
    Assert.True(cached.Code == 0, cached.Error);
    Assert.Equal([profile, script], Directory.GetFiles(startup).Order());
    Assert.Equal(before, File.ReadAllBytes(profile));
    Assert.True(File.GetLastWriteTimeUtc(profile) < DateTime.UtcNow.AddMinutes(-30));
    Assert.True(File.GetLastWriteTimeUtc(script) > DateTime.UtcNow.AddMinutes(-30));

    // An edited script compiles again, replaying and rewriting the profile.
    File.AppendAllText(dir.File("s.cs"), "// edited\n");
    var edited = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, env, render));
    Assert.True(edited.Code == 0, edited.Error);
    Assert.True(File.GetLastWriteTimeUtc(profile) > DateTime.UtcNow.AddMinutes(-30));
  }

  [Theory]
  [InlineData(true, false)]
  [InlineData(false, true)]
  public void No_profile_is_written_when_the_cache_is_off(bool noCacheVariable, bool noCacheOption)
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    var env = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache };
    if (noCacheVariable)
      env[ScriptCache.DisableVariable] = "1";
    string[] args = ["info", "fiveballs", .. noCacheOption ? new[] { "--no-cache" } : []];
    var r = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, env, args));
    Assert.True(r.Code == 0, r.Error);
    Assert.False(Directory.Exists(Path.Combine(cache, "startup")));
  }
  [Theory]
  [InlineData("random")]
  [InlineData("cut")]
  [InlineData("flipped")]
  public void A_damaged_profile_costs_nothing_but_its_speed_up(string damage)
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    var cached = new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache };
    string[] render = ["render", "fiveballs", "--size", "32x24", "--spp", "4", "-q"];
    var first = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, cached, [.. render, "-o", "first.png"]));
    Assert.True(first.Code == 0, first.Error);
    string profile = Assert.Single(Directory.GetFiles(Path.Combine(cache, "startup"), "render-*" + StartupProfile.Extension));
    byte[] bytes = File.ReadAllBytes(profile);
    var random = new Random(7);
    switch (damage)
    {
      case "random":
        random.NextBytes(bytes);
        break;
      case "cut":
        bytes = bytes[..(bytes.Length / 2 + 3)];
        break;
      default:
        // The header stays; records after it get random bits.
        for (int i = 64; i < bytes.Length; i += 1 + random.Next(40))
          bytes[i] ^= (byte)(1 << random.Next(8));
        break;
    }
    File.WriteAllBytes(profile, bytes);

    var damaged = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, cached, [.. render, "-o", "damaged.png"]));

    Assert.True(damaged.Code == 0, damaged.Error);
    Assert.Equal(File.ReadAllBytes(dir.File("first.png")), File.ReadAllBytes(dir.File("damaged.png")));
  }
  [UnixFact]
  public void The_cache_and_profile_folders_it_creates_are_private_to_the_user()
  {
    using var dir = new TempDirectory();
    string cache = dir.File("cache");
    var r = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache }, "list"));
    Assert.True(r.Code == 0, r.Error);
    var owner = UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute;
    Assert.Equal(owner, File.GetUnixFileMode(cache));
    Assert.Equal(owner, File.GetUnixFileMode(Path.Combine(cache, "startup")));
  }

  [UnixFact]
  public void No_profile_is_read_or_written_in_a_cache_folder_others_may_write()
  {
    using var dir = new TempDirectory();
    string cache = Directory.CreateDirectory(dir.File("cache")).FullName;
    string startup = Directory.CreateDirectory(Path.Combine(cache, "startup")).FullName;
    var open = (UnixFileMode)Convert.ToInt32("777", 8);
    File.SetUnixFileMode(cache, open);
    File.SetUnixFileMode(startup, open);
    // A profile planted by someone else is left alone, and no new one is written.
    string planted = Path.Combine(startup, StartupProfile.FileName("render", StartupProfile.BuildId()));
    File.WriteAllText(planted, "planted");
    var r = GrcisProcess.Finish(GrcisProcess.Start(dir.Path, new Dictionary<string, string> { [ScriptCache.DirectoryVariable] = cache },
                                                   "render", "fiveballs", "--size", "16x12", "-q", "-o", "a.png"));
    Assert.True(r.Code == 0, r.Error);
    Assert.Equal("planted", File.ReadAllText(planted));
    Assert.Equal([planted], Directory.GetFiles(startup));
  }
}
