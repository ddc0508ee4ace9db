using System.CommandLine;
using GrCis.Cli.SceneSources;

namespace GrCis.Cli.Commands;

/// <summary><c>grcis list</c>: the built-in scene names, one per line, in GrCis's order.</summary>
public static class ListCommand
{
  public static Command Build(CliEnvironment env)
  {
    var cmd = new Command("list", "List the built-in scenes");
    cmd.SetAction(_ =>
    {
      foreach (string name in SceneResolver.BuiltInNames)
        env.Out.WriteLine(name);
      return ExitCodes.Success;
    });
    return cmd;
  }
}
