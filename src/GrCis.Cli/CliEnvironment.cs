using System;
using System.IO;
using System.Threading;
using GrCis.Scripting.Caching;

namespace GrCis.Cli;

/// <summary>Where a command reads and writes: the real console in <c>Main</c>, captured writers in tests.</summary>
public sealed record CliEnvironment
{
  public CliEnvironment(TextWriter output, TextWriter error)
  {
    Out = output ?? throw new ArgumentNullException(nameof(output));
    Error = error ?? throw new ArgumentNullException(nameof(error));
  }

  /// <summary>Results (the final summary line, <c>list</c> output).</summary>
  public TextWriter Out { get; }

  /// <summary>Errors and progress.</summary>
  public TextWriter Error { get; }

  /// <summary>True when stderr is a terminal: show a live progress bar instead of plain lines.</summary>
  public bool Interactive { get; init; }

  /// <summary>Relative paths (and the default output file) resolve against this directory.</summary>
  public string WorkingDirectory { get; init; } = Directory.GetCurrentDirectory();

  /// <summary>
  /// True when grcis is the whole process (<c>Main</c>): settings of the process itself, the heap limit of
  /// <c>--memory-limit</c>, apply. A test that runs grcis in its own process leaves them alone.
  /// </summary>
  public bool OwnsProcess { get; init; }

  /// <summary>Signalled by Ctrl+C; a cancelled render writes nothing.</summary>
  public CancellationToken Cancel { get; init; }

  /// <summary>
  /// Print the whole exception (type, message, stack, inner exceptions) after an error's one line, for a bug
  /// report: <c>GRCIS_STACKTRACE=1</c> in the environment.
  /// </summary>
  public bool StackTraces { get; init; } = Environment.GetEnvironmentVariable(StackTraceVariable) is "1" or "true" or "yes";

  /// <summary>The environment variable that asks for <see cref="StackTraces"/>.</summary>
  public const string StackTraceVariable = "GRCIS_STACKTRACE";

  /// <summary>
  /// Where compiled scene scripts are kept between runs: by default the one the environment asks for
  /// (<see cref="ScriptCache.FromEnvironment"/>: the platform's cache folder or <c>GRCIS_CACHE_DIR</c>; none with
  /// <c>GRCIS_NO_CACHE=1</c>); null = none. <c>--no-cache</c> leaves it unused for one command.
  /// </summary>
  public ScriptCache? ScriptCache { get; init; } = ScriptCache.FromEnvironment();

  /// <summary>
  /// Called before a scene script or module is compiled (a miss of both caches): <c>Main</c> starts the compiler's
  /// multicore JIT profile there (<see cref="StartupProfile.CompileHook"/>); null when grcis runs inside a test's
  /// process. Not used with <c>--no-cache</c>.
  /// </summary>
  public Action? BeforeCompile { get; init; }

  /// <summary>The same environment with another cancellation (one pass of <c>--watch</c>, cancelled by the next save).</summary>
  public CliEnvironment WithCancel(CancellationToken cancel) => this with { Cancel = cancel };

  /// <summary>Scenes a test registers by name, tried before the resolver (the tests' animated scenes).</summary>
  internal Func<string, GrCis.Hosting.ISceneSource?>? ExtraScenes { get; init; }
}
