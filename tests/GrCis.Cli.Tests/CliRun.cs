using System.IO;
using System.Threading;

namespace GrCis.Cli.Tests;

/// <summary>Runs <c>grcis</c> in-process through <see cref="Program.Run(string[], CliEnvironment)"/> with captured output.</summary>
internal sealed record CliRun(int ExitCode, string Out, string Error)
{
  public static CliRun Of(string workingDirectory, params string[] args) => Of(workingDirectory, CancellationToken.None, args);

  public static CliRun Of(string workingDirectory, CancellationToken cancel, params string[] args)
  {
    var output = new StringWriter();
    var error = new StringWriter();
    var env = new CliEnvironment(output, error) { WorkingDirectory = workingDirectory, Cancel = cancel };
    int code = Program.Run(args, env);
    return new CliRun(code, output.ToString(), error.ToString());
  }

  public string[] ErrorLines => Error.Split('\n', System.StringSplitOptions.RemoveEmptyEntries | System.StringSplitOptions.TrimEntries);
}
