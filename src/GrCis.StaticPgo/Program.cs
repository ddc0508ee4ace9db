using System;
using System.CommandLine;
using System.IO;
using System.Linq;

namespace GrCis.StaticPgo;

/// <summary>
/// <c>train</c>: runs the training commands with grcis (a copy precompiled for this machine, given the ReadyToRun compiler) and writes the static profile of the given
/// assemblies; <c>convert</c>: writes it from text dumps made elsewhere.
/// </summary>
internal static class Program
{
  static int Main(string[] args)
  {
    var output = new Option<FileInfo>("--output", "-o") { Description = "The profile to write (.mibc)", Required = true };
    var assemblies = new Option<FileInfo[]>("--assembly", "-a")
    {
      Description = "An assembly whose methods the profile describes (repeatable)", Required = true,
    };

    var dumps = new Argument<FileInfo[]>("dumps") { Description = "Text dumps (DOTNET_WritePGOData)", Arity = ArgumentArity.OneOrMore };
    var convert = new Command("convert", "Write the profile from text dumps") { output, assemblies, dumps };
    convert.SetAction(parse => Write(parse.GetValue(dumps)!.Select(f => f.FullName).ToArray(), parse.GetValue(assemblies)!, parse.GetValue(output)!));

    var runs = new Option<FileInfo>("--runs") { Description = "The training commands, one a line", Required = true };
    var grcis = new Option<FileInfo>("--grcis") { Description = "The built grcis.dll to train (copied and precompiled with --crossgen)", Required = true };
    var dotnet = new Option<string>("--dotnet") { Description = "The dotnet host", DefaultValueFactory = _ => "dotnet" };
    var work = new Option<DirectoryInfo>("--work") { Description = "A folder for the dumps and the runs' files", Required = true };
    var root = new Option<DirectoryInfo>("--root") { Description = "The folder the runs start in (paths in the commands)", Required = true };
    var crossgen = new Option<FileInfo?>("--crossgen")
    {
      Description = "The ReadyToRun compiler: the training runs a copy of grcis with the assemblies compiled ahead of time",
    };
    var train = new Command("train", "Run the training and write the profile") { output, assemblies, runs, grcis, dotnet, work, root, crossgen };
    train.SetAction(parse =>
    {
      string trained = parse.GetValue(grcis)!.FullName, folder = parse.GetValue(work)!.FullName;
      if (parse.GetValue(crossgen) is { } compiler)
        trained = TrainingBuild.Prepare(compiler.FullName, Path.GetDirectoryName(trained)!,
          parse.GetValue(assemblies)!.Select(a => a.FullName).ToArray(), Path.Combine(folder, "app"), Console.Out);
      var dumped = TrainingRuns.Run(parse.GetValue(dotnet)!, trained, TrainingRuns.Read(parse.GetValue(runs)!.FullName),
        folder, parse.GetValue(root)!.FullName, Console.Out);
      return Write(dumped.ToArray(), parse.GetValue(assemblies)!, parse.GetValue(output)!);
    });

    var command = new RootCommand("grcis's static profile for its ReadyToRun compilation") { train, convert };
    try
    {
      return command.Parse(args).Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
    }
    catch (Exception e) when (e is InvalidOperationException or FormatException or IOException or BadImageFormatException)
    {
      Console.Error.WriteLine("static profile: " + e.Message);
      return 1;
    }
    catch (AggregateException e) when (e.InnerExceptions.All(inner => inner is InvalidOperationException))
    {
      // The training build's compilations run in parallel: each failure's own message.
      foreach (Exception inner in e.InnerExceptions) Console.Error.WriteLine("static profile: " + inner.Message);
      return 1;
    }
  }

  static int Write(string[] dumps, FileInfo[] assemblies, FileInfo output)
  {
    var builder = new ProfileBuilder();
    foreach (string dump in dumps) builder.AddRun(PgoTextDump.Read(dump));
    // Written beside and moved, so an interrupted run leaves no half profile for the compiler.
    string partial = output.FullName + ".partial";
    Directory.CreateDirectory(output.DirectoryName!);
    int count;
    using (var file = File.Create(partial))
      count = builder.Write(assemblies.Select(a => a.FullName), file, Path.GetFileNameWithoutExtension(output.Name), TextWriter.Null);
    File.Move(partial, output.FullName, overwrite: true);
    Console.WriteLine($"static profile: {count} of {builder.DumpedMethods} profiled methods, {output.FullName}");
    return 0;
  }
}
