using System;
using System.Collections.Generic;
using System.CommandLine;
using System.IO;
using System.Linq;
using GrCis.Cli.Watching;

namespace GrCis.Cli.Commands;

/// <summary><c>--watch</c> of <c>render</c> and <c>animate</c>: render again on each save of the script, its modules or its data files (<see cref="WatchLoop"/>).</summary>
public sealed class WatchOption
{
  readonly Option<bool> option;

  /// <param name="what">What each pass renders, for the help ("the image", "the first frame, or --frames a-b").</param>
  public WatchOption(string what)
  {
    option = new("--watch", "-w")
    {
      Description = $"Stay running: render {what} again each time the script, a --module file or a data file the scene read is saved " +
                    "(errors are printed and the last good image kept); Ctrl+C to stop",
    };
  }

  public void AddTo(Command cmd) => cmd.Options.Add(option);

  public bool IsSet(ParseResult parse) => parse.GetValue(option);

  /// <summary>Runs <paramref name="runPass"/> now and after every save until Ctrl+C.</summary>
  /// <exception cref="UsageException">The scene is not a script file: there is nothing to watch.</exception>
  public static int Run(CliEnvironment env, string? scene, IEnumerable<string> modules, Func<CliEnvironment, int> runPass)
  {
    if (scene == null || !scene.EndsWith(".cs", StringComparison.OrdinalIgnoreCase))
      throw new UsageException("--watch needs a scene script (*.cs): a built-in scene does not change");
    string script = Path.GetFullPath(scene, env.WorkingDirectory);
    string[] folders = modules.Select(m => Path.GetFullPath(m, env.WorkingDirectory)).ToArray();
    return new WatchLoop(env, [script], folders).Run(runPass);
  }
}
