using System;
using System.CommandLine;
using System.IO;
using System.Threading;
using GrCis.Cli.Commands;
using Rendering.Execution;

namespace GrCis.Cli;

/// <summary>
/// Entry point of <c>grcis</c>. <see cref="Run(string[], TextWriter, TextWriter)"/> is the whole
/// program with its console passed in, so tests run it in-process.
/// </summary>
public static class Program
{
  public static int Main(string[] args)
  {
    StartupProfile.Start(args);
    using var interrupt = new InterruptGuard(Console.Error);
    var env = new CliEnvironment(Console.Out, Console.Error)
    {
      Interactive = !Console.IsErrorRedirected && !Console.IsOutputRedirected &&
                    Environment.GetEnvironmentVariable("TERM") is not "dumb",
      Cancel = interrupt.Token,
      OwnsProcess = true,
      BeforeCompile = StartupProfile.CompileHook(args),
    };
    return Run(args, env);
  }

  /// <summary>Runs <c>grcis</c> with plain (non-interactive) progress, writing to the given writers.</summary>
  public static int Run(string[] args, TextWriter output, TextWriter error) =>
    Run(args, new CliEnvironment(output, error));

  public static int Run(string[] args, CliEnvironment env)
  {
    ArgumentNullException.ThrowIfNull(args);
    ArgumentNullException.ThrowIfNull(env);
    try
    {
      RootCommand root = BuildRoot(env);
      ParseResult parse = root.Parse(args);
      if (TypoSuggestions.Find(parse) is { } typo)
        return Fail(env, ExitCodes.Usage, typo);
      if (parse.Errors.Count > 0)
        return Fail(env, ExitCodes.Usage, parse.Errors[0].Message + " (see 'grcis --help')");

      var config = new InvocationConfiguration
      {
        Output = env.Out,
        Error = env.Error,
        EnableDefaultExceptionHandler = false,
        ProcessTerminationTimeout = null,
      };
      // A script stuck in a loop while it builds the scene obeys Ctrl+C too (see Interruption).
      using Interruption.Scope interruption = Interruption.Use(env.Cancel);
      return parse.Invoke(config);
    }
    catch (Exception e)
    {
      return Report(env, e);
    }
    finally
    {
      env.Out.Flush();
      env.Error.Flush();
    }
  }

  /// <summary>
  /// Writes the one line (or, for a script that did not compile, the lines) a failed command prints and returns its exit
  /// code; <c>render --watch</c> reports a failed pass the same way and goes on watching.
  /// </summary>
  internal static int Report(CliEnvironment env, Exception e)
  {
    switch (e)
    {
      case OperationCanceledException when env.Cancel.IsCancellationRequested:
        return Fail(env, ExitCodes.Cancelled, "cancelled while the scene script ran; nothing written");
      case Exception when ScriptErrors.Handles(e):
        return WithStack(env, e, ScriptErrors.Report(e, env));
      case UsageException:
        return Fail(env, ExitCodes.Usage, e.Message);
      case CliFailure:
        return WithStack(env, e, Fail(env, ExitCodes.Failure, e.Message));
      case RenderException:
        return WithStack(env, e, Fail(env, ExitCodes.Failure, "render failed: " + ErrorMessages.OneLine(e.InnerException ?? e)));
      case OutOfMemoryException:
        // The heap limit (--memory-limit) was reached outside a script's code; what was allocated is garbage by now.
        return WithStack(env, e, Fail(env, ExitCodes.Failure, "out of memory: " + e.Message + Jobs.MemoryLimit.Hint()));
      default:
        // Scene construction and loaders (OBJ meshes, scripts) report here, with file(line) when they know it.
        return WithStack(env, e, Fail(env, ExitCodes.Failure, ErrorMessages.OneLine(e)));
    }
  }

  static RootCommand BuildRoot(CliEnvironment env)
  {
    var root = new RootCommand("grcis: the GrCis ray tracer on .NET")
    {
      new RenderCommand().Build(env),
      new AnimateCommand().Build(env),
      new MergeCommand().Build(env),
      ListCommand.Build(env),
      new InfoCommand().Build(env),
      new ExportCommand().Build(env),
      BenchCommand.Build(env),
      new StudioCommand().Build(env),
      InitCommand.Build(env),
    };
    return root;
  }

  /// <summary>After the error's line, the whole exception when the user asked for it (<see cref="CliEnvironment.StackTraces"/>).</summary>
  static int WithStack(CliEnvironment env, Exception e, int code)
  {
    if (env.StackTraces)
      env.Error.WriteLine(e.ToString());
    return code;
  }

  static int Fail(CliEnvironment env, int code, string message)
  {
    env.Error.WriteLine("grcis: error: " + message);
    return code;
  }
}
