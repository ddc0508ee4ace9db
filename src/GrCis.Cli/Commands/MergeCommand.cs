using System;
using System.Collections.Generic;
using System.CommandLine;
using System.IO;
using GrCis.Cli.Output;
using Rendering.Parts;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis merge PARTS… -o out.png|pfm</c>: assembles the parts written by <c>render --tiles i/n</c>
/// into the image one process would have rendered, byte for byte. Refuses (and writes nothing) when
/// parts are missing, repeated, damaged or from different renders.
/// </summary>
public sealed class MergeCommand
{
  readonly Argument<string[]> parts = new("parts")
  {
    Description = "The part files (*.grcis-part), every part of one render, in any order",
    Arity = ArgumentArity.OneOrMore,
  };

  readonly Option<string?> output = new("--output", "-o")
  {
    Description = "Merged image (.png or .pfm)",
    HelpName = "file",
    Required = true,
  };

  readonly Option<string?> format = new("--format")
  {
    Description = "png or pfm (linear float); default: from the output file's extension",
  };

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("merge", "Assemble the parts of a still rendered with 'render --tiles i/n'")
    {
      parts, output, format,
    };
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    OutputTarget target = OutputTarget.Resolve(parse.GetValue(output), parse.GetValue(format), "merged", env.WorkingDirectory);
    if (target.Format == OutputFormat.Part)
      throw new UsageException("merge writes a .png or .pfm image, not a part file");
    target.CheckWritable();

    var loaded = new List<(string, PartHeader, float[])>();
    foreach (string file in parse.GetValue(parts) ?? [])
    {
      string path = Path.GetFullPath(file, env.WorkingDirectory);
      if (Directory.Exists(path))
        throw new UsageException($"'{file}' is a directory; give the part files (e.g. '{Path.Combine(file, "*" + PartFile.Extension)}')");
      try
      {
        (PartHeader h, float[] samples) = PartFile.Load(path);
        loaded.Add((file, h, samples));
      }
      catch (Exception e) when (e is IOException or UnauthorizedAccessException)
      {
        // InvalidDataException already reads "path: reason".
        throw new CliFailure(e is InvalidDataException ? e.Message : $"cannot read '{file}': {e.Message}", e);
      }
    }

    try
    {
      (var image, PartHeader header) = PartMerge.Merge(loaded);
      target.Save(image, header.Gamma);
      env.Out.WriteLine($"wrote {target.FullPath}: {header.Width}x{header.Height} from {header.Count} parts of {header.Scene}");
    }
    catch (PartMergeException e)
    {
      throw new CliFailure($"cannot merge: {e.Message}; '{target.FullPath}' not written", e);
    }
    return ExitCodes.Success;
  }
}
