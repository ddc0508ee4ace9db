using System;
using System.Collections.Generic;
using System.CommandLine;
using System.IO;
using GrCis.Cli.Scaffolding;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis init [DIR]</c>: a scene script folder an IDE understands, the files <c>dotnet new grcis-scene</c>
/// makes (Scene.cs, a project named after the folder, the globals shim), without the template engine.
/// </summary>
public static class InitCommand
{
  public static Command Build(CliEnvironment env)
  {
    var dir = new Argument<string?>("dir")
    {
      Description = "Folder to create the scene in (made when missing); default: the current folder",
      Arity = ArgumentArity.ZeroOrOne,
    };
    var cmd = new Command("init", "Create a scene script folder (Scene.cs and a project for IntelliSense and dotnet build), as dotnet new grcis-scene does") { dir };
    cmd.SetAction(parse => Execute(parse.GetValue(dir), env));
    return cmd;
  }

  static int Execute(string? dir, CliEnvironment env)
  {
    string folder = Path.GetFullPath(Path.Combine(env.WorkingDirectory, string.IsNullOrEmpty(dir) ? "." : dir));
    if (File.Exists(folder))
      throw new UsageException($"{folder}: is a file; grcis init needs a folder (a new or an existing one)");
    string name = Path.GetFileName(Path.TrimEndingDirectorySeparator(folder));
    if (name.Length == 0)
      throw new UsageException($"{folder}: the project is named after the folder, and this one has no name; give a folder below it");

    IReadOnlyList<string> written = SceneFolderWriter.Write(folder, SceneFolderTemplate.Files(name));
    foreach (string file in written)
      env.Out.WriteLine("created " + Path.GetRelativePath(env.WorkingDirectory, file));
    string cd = Path.GetRelativePath(env.WorkingDirectory, folder);
    env.Out.WriteLine($"next: {(cd == "." ? "" : $"cd {Quote(cd)}; ")}dotnet build (checks Scene.cs); grcis render Scene.cs -o scene.png; or open the folder in your IDE");
    return ExitCodes.Success;
  }

  static string Quote(string path) => path.Contains(' ', StringComparison.Ordinal) ? $"\"{path}\"" : path;
}
