using System;
using System.IO;
using System.Linq;
using System.Runtime;
using System.Threading;
using GrCis.Scripting.Caching;

namespace GrCis.Cli;

/// <summary>
/// Multicore JIT for grcis's own start (<see cref="ProfileOptimization"/>). A run of a command records which methods
/// it compiled into a profile; the next run of that command compiles them on a second core while the first one
/// parses the command line, builds the scene and starts the render, instead of each waiting for the JIT when it is
/// first called. The profiles live in the <c>startup</c> folder of the compiled-script cache, one per command and
/// build, the newest <see cref="Kept"/> kept (pruned when a run adds one). Off when the cache is
/// (<c>GRCIS_NO_CACHE=1</c>, <c>--no-cache</c>, no cache folder) and for <c>init</c>; <c>studio</c> has one for its
/// supervisor and one for the studio process (<see cref="StudioProfile"/>). A scene script's run has two, one until it
/// compiles the script or a module and one from then on (<see cref="CompileHook"/>): a run that finds its script
/// compiled in the cache must not replay the compiler.
/// A profile that is missing, another build's or unreadable only costs its speed-up; a folder another user could write
/// (as the cache's trust rule says) is not used.
/// </summary>
static class StartupProfile
{
  /// <summary>Profiles kept in the folder (several builds and commands); older ones are deleted.</summary>
  internal const int Kept = 16;

  internal const string Extension = ".jitprofile";

  static readonly string[] commands = { "render", "animate", "merge", "list", "info", "bench" };

  /// <summary>
  /// Starts recording, and replaying the last profile of this command and build, when the cache is on: the command's own
  /// for a built-in scene, <c>&lt;command&gt;-script</c> for a scene script (see <see cref="CompileHook"/>).
  /// </summary>
  public static void Start(string[] args)
  {
    if (Applies(args))
      Begin(args[0]);
    else if (RunsScript(args))
      Begin(args[0] + ScriptSuffix);
    else if (StudioProfile(args) is string studio)
      Begin(studio);
  }

  /// <summary>
  /// The profile of a <c>studio</c> run: <c>studio</c> for the supervisor the user starts, <c>studio-server</c> for the
  /// studio process it runs (ASP.NET Core, the editor's language services and the compiler, always loaded there, so
  /// scripts change nothing). Null for other commands.
  /// </summary>
  internal static string? StudioProfile(string[] args) =>
    args.Length == 0 || args[0] != "studio" ? null
    : Array.IndexOf(args, GrCis.Studio.StudioSupervisor.PublicPortOption) >= 0 ? "studio-server" : "studio";

  /// <summary>
  /// What <see cref="CliEnvironment.BeforeCompile"/> does in a real process that runs a scene script: its first compilation
  /// switches from the profile <c>&lt;command&gt;-script</c> to <c>&lt;command&gt;-compile</c> (a new start stops the
  /// recording in progress and writes it). So only runs that compile record and replay the compiler (about 3,000
  /// methods JIT-compiled in a fresh process, most of its start), and a run that finds its script in the cache replays
  /// the script profile without the compiler. Null where <see cref="Start"/> uses the command's profile (no script),
  /// for commands without profiles and with <c>--no-cache</c>.
  /// </summary>
  public static Action? CompileHook(string[] args)
  {
    if (!RunsScript(args))
      return null;
    string name = args[0] + CompileSuffix;
    int started = 0;
    return () =>
    {
      if (Interlocked.Exchange(ref started, 1) == 0)
        Begin(name);
    };
  }

  /// <summary>
  /// Stops the recording in progress and writes its profile now (nothing when none is recording): for a process that
  /// will not end on its own, as the studio process, which its supervisor ends by killing it.
  /// </summary>
  public static void Finish() => ProfileOptimization.StartProfile(null);

  /// <summary>The profile name's suffix for a run that compiles a scene script or module.</summary>
  internal const string CompileSuffix = "-compile";

  /// <summary>The profile name's suffix for a scene script's run, until it compiles.</summary>
  internal const string ScriptSuffix = "-script";

  /// <summary>A command with profiles running a scene script, the cache not bypassed.</summary>
  static bool RunsScript(string[] args) => Profiled(args) && HasScript(args);

  /// <summary>Records the profile <paramref name="name"/> of this build, replaying the last one, when the cache is on.</summary>
  static void Begin(string name)
  {
    if (ScriptCache.FromEnvironment() is not ScriptCache cache)
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
      string file = FileName(name, BuildId());
      // Only a run that adds a profile can take the folder past Kept; listing it costs a run ~10 ms of its start.
      if (!File.Exists(Path.Combine(folder, file)))
        Prune(folder, Kept - 1);
      ProfileOptimization.SetProfileRoot(folder);
      ProfileOptimization.StartProfile(file);
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

  /// <summary>Whether a run with these arguments gets its command's profile: one of <see cref="commands"/>, no script, no <c>--no-cache</c>.</summary>
  internal static bool Applies(string[] args) => Profiled(args) && !HasScript(args);

  /// <summary>One of <see cref="commands"/>, without <c>--no-cache</c>.</summary>
  static bool Profiled(string[] args) =>
    args.Length > 0 && Array.IndexOf(commands, args[0]) >= 0 && Array.IndexOf(args, "--no-cache") < 0;

  /// <summary>An argument ending in <c>.cs</c>: the scene is a script.</summary>
  static bool HasScript(string[] args)
  {
    foreach (string a in args)
      if (a.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
        return true;
    return false;
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
