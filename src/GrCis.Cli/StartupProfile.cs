using System;
using System.IO;
using System.Linq;
using System.Runtime;
using GrCis.Scripting.Caching;

namespace GrCis.Cli;

/// <summary>
/// Multicore JIT for grcis's own start (<see cref="ProfileOptimization"/>). A run of a command records which methods
/// it compiled into a profile; the next run of that command compiles them on a second core while the first one
/// parses the command line, builds the scene and starts the render, instead of each waiting for the JIT when it is
/// first called. The profiles live in the <c>startup</c> folder of the compiled-script cache, one per command and
/// build, the newest <see cref="Kept"/> kept (pruned when a run adds one). Off when the cache is (<c>GRCIS_NO_CACHE=1</c>, <c>--no-cache</c>, no
/// cache folder), for <c>studio</c> and <c>init</c>, and for scene scripts: a run that compiles a script would record
/// the compiler, and replaying that would load it in a later run that finds the script compiled in the cache.
/// A profile that is missing, another build's or unreadable only costs its speed-up; a folder another user could write
/// (as the cache's trust rule says) is not used.
/// </summary>
static class StartupProfile
{
  /// <summary>Profiles kept in the folder (several builds and commands); older ones are deleted.</summary>
  internal const int Kept = 16;

  internal const string Extension = ".jitprofile";

  static readonly string[] commands = { "render", "animate", "merge", "list", "info", "bench" };

  /// <summary>Starts recording, and replaying the last profile of this command and build, when the cache is on.</summary>
  public static void Start(string[] args)
  {
    if (!Applies(args) || ScriptCache.FromEnvironment() is not ScriptCache cache)
      return;
    try
    {
      string folder = Path.Combine(cache.Directory, "startup");
      CreatePrivate(cache.Directory);
      CreatePrivate(folder);
      // A profile steers what the JIT compiles: none from a folder another user could have written (the cache itself
      // says so when a script asks it).
      if (ScriptCache.WhyUntrusted(cache.Directory) != null || ScriptCache.WhyUntrusted(folder) != null)
        return;
      string name = FileName(args[0], BuildId());
      // Only a run that adds a profile can take the folder past Kept; listing it costs a run ~10 ms of its start.
      if (!File.Exists(Path.Combine(folder, name)))
        Prune(folder, Kept - 1);
      ProfileOptimization.SetProfileRoot(folder);
      ProfileOptimization.StartProfile(name);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      // A read-only or missing home folder: run without the profile.
    }
  }

  /// <summary>A folder of the cache, private to the user on Unix as the cache's own (it holds what steers the JIT).</summary>
  static void CreatePrivate(string folder)
  {
    if (OperatingSystem.IsWindows())
      Directory.CreateDirectory(folder);
    else
      Directory.CreateDirectory(folder, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
  }

  /// <summary>Whether a run with these arguments gets a profile: one of <see cref="commands"/>, no script, no <c>--no-cache</c>.</summary>
  internal static bool Applies(string[] args)
  {
    if (args.Length == 0 || Array.IndexOf(commands, args[0]) < 0 || Array.IndexOf(args, "--no-cache") >= 0)
      return false;
    foreach (string a in args)
      if (a.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
        return false;
    return true;
  }

  /// <summary>The profile's file name: the command and the build.</summary>
  internal static string FileName(string command, string build) => command + "-" + build + Extension;

  /// <summary>
  /// A short hash of grcis's own assemblies' module version ids: a rebuilt library gets a profile of its own, so two
  /// builds run in turn (a benchmark) do not overwrite each other's.
  /// </summary>
  internal static string BuildId()
  {
    // FNV-1a over the ids (no cryptography: loading it would cost more start-up than the profile saves).
    ulong h = 14695981039346656037UL;
    foreach (Type t in new[] { typeof(Program), typeof(GrCis.Hosting.RenderRequest), typeof(Rendering.RayTracing), typeof(ScriptCache) })
      foreach (byte b in t.Module.ModuleVersionId.ToByteArray())
        h = (h ^ b) * 1099511628211UL;
    return h.ToString("x16");
  }

  /// <summary>Deletes all but the <paramref name="keep"/> most recently written profiles in <paramref name="folder"/>.</summary>
  internal static void Prune(string folder, int keep)
  {
    FileInfo[] profiles = new DirectoryInfo(folder).GetFiles("*" + Extension);
    if (profiles.Length <= keep)
      return;
    foreach (FileInfo old in profiles.OrderByDescending(f => f.LastWriteTimeUtc).Skip(keep))
    {
      try
      {
        old.Delete();
      }
      catch (Exception e) when (e is IOException or UnauthorizedAccessException)
      {
        // Another grcis may be deleting or writing it at the same time.
      }
    }
  }
}
