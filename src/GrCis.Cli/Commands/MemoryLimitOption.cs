using System.CommandLine;
using GrCis.Cli.Jobs;

namespace GrCis.Cli.Commands;

/// <summary><c>--memory-limit</c> of the commands that run scene scripts for long (<c>render</c>, <c>animate</c>): see <see cref="MemoryLimit"/>.</summary>
public sealed class MemoryLimitOption
{
  readonly Option<string?> option = new("--memory-limit")
  {
    Description = "Most memory grcis may use (e.g. 4G, 512M, 50%); a script that allocates more stops with an error naming its line " +
                  "instead of being killed. Default: 75% of the memory available; 0 or none: no limit",
    HelpName = "size",
  };

  public void AddTo(Command cmd) => cmd.Options.Add(option);

  /// <summary>The value as given on the command line; null when not given (the default applies).</summary>
  public string? Given(ParseResult parse) => parse.GetValue(option);

  /// <summary>Checks the value; sets the limit when grcis owns the process (<see cref="CliEnvironment.OwnsProcess"/>).</summary>
  /// <exception cref="UsageException">A malformed value, or one below what grcis already uses.</exception>
  public void Apply(ParseResult parse, CliEnvironment env)
  {
    string? text = parse.GetValue(option);
    if (env.OwnsProcess)
      MemoryLimit.Apply(text);
    else if (text != null)
      MemoryLimit.Resolve(text, MemoryLimit.TotalAvailable, setByEnvironment: false);
  }
}
