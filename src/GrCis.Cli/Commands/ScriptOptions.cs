using System;
using System.CommandLine;
using GrCis.Cli.SceneSources;

using GrCis.Hosting;
using GrCis.Scripting.Caching;

namespace GrCis.Cli.Commands;

/// <summary>
/// The options commands share for scene scripts: <c>--param</c> (the script's <c>param</c> text),
/// <c>--module DIR</c> (repeatable), <c>--no-cache</c> and <c>--time T</c>. Used by <c>render</c>, <c>animate</c> and <c>info</c>.
/// </summary>
public sealed class ScriptOptions
{
  public Option<string?> Param { get; } = new("--param", "-p")
  {
    Description = "Parameters for the scene: free text, usually \"key=value, key2\" (a bare key means true)",
    HelpName = "text",
  };

  public Option<string[]> Modules { get; } = new("--module", "-m")
  {
    Description = "Folder of .cs files (a GrCis module) compiled for the script to use; repeatable",
    HelpName = "DIR",
    AllowMultipleArgumentsPerToken = false,
  };

  public Option<double?> TimeOption { get; } = new("--time")
  {
    Description = "Time (seconds) at which to render an animated scene; default: the script's Time or its start",
    HelpName = "T",
  };

  public Option<bool> NoCache { get; } = new("--no-cache")
  {
    Description = $"Compile the scene script and its modules afresh, without reading or writing the compiled-script cache (also {ScriptCache.DisableVariable}=1)",
  };

  /// <summary>Adds the options to <paramref name="cmd"/> (<paramref name="withTime"/>: also <c>--time</c>).</summary>
  public void AddTo(Command cmd, bool withTime = true)
  {
    cmd.Options.Add(Param);
    cmd.Options.Add(Modules);
    cmd.Options.Add(NoCache);
    if (withTime)
      cmd.Options.Add(TimeOption);
  }

  public double? Time(ParseResult parse)
  {
    double? t = parse.GetValue(TimeOption);
    if (t is double v && !double.IsFinite(v))
      throw new UsageException($"invalid --time {v}: must be a finite number of seconds");
    return t;
  }

  /// <summary>The scene source for the scene argument, with the script options applied.</summary>
  public ISceneSource Resolve(ParseResult parse, string? scene, CliEnvironment env) =>
    new SceneResolver(env.WorkingDirectory).Resolve(scene, parse.GetValue(Param), parse.GetValue(Modules) ?? Array.Empty<string>(),
                                                    parse.GetValue(NoCache) ? null : env.ScriptCache,
                                                    parse.GetValue(NoCache) ? null : env.BeforeCompile);
}
