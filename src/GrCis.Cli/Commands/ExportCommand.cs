using System;
using System.CommandLine;
using System.IO;
using System.Linq;
using GrCis.Cli.Jobs;
using GrCis.Cli.Output;
using GrCis.Cli.SceneSources;
using GrCis.Hosting;
using GrCis.Hosting.Export;
using Rendering.Tessellation;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis export scene.cs -o scene.glb|scene.gltf [--time T] [--param …]</c>: the scene as glTF 2.0 for Blender or any
/// 3D viewer — every solid tessellated with its transform and colour, the camera, the lights (docs/export.md).
/// </summary>
public sealed class ExportCommand
{
  readonly Argument<string?> scene = new("scene")
  {
    Description = $"Built-in scene name (see 'grcis list') or a scene script (*.cs); default: \"{SceneResolver.DefaultSceneName}\"",
    Arity = ArgumentArity.ZeroOrOne,
  };

  readonly Option<string?> output = new("--output", "-o")
  {
    Description = "The glTF file: .glb (binary, one file) or .gltf (JSON with a .bin beside it); default: <scene>.glb",
    HelpName = "FILE",
  };

  readonly Option<string?> size = new("--size", "-s")
  {
    Description = "Image size WIDTHxHEIGHT the camera's aspect ratio and field of view follow; default: the script's, else 640x480",
    HelpName = "WxH",
  };

  readonly Option<bool> quiet = new("--quiet", "-q") { Description = "Print nothing on success (notes still go to stderr)" };
  readonly ScriptOptions scriptOptions = new();

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("export", "Write a scene as glTF 2.0 (.glb or .gltf): its solids as triangles, the camera, the lights")
    {
      scene, output, size, quiet,
    };
    scriptOptions.AddTo(cmd);
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    // Usage errors first, before the script runs and before anything is written.
    (RenderSettings settings, GivenSettings given) = ReadSize(parse.GetValue(size));
    ISceneSource source = scriptOptions.Resolve(parse, parse.GetValue(scene), env);
    using var scriptHost = source as IDisposable;
    string path = ResolveOutput(parse.GetValue(output), source.OutputStem, env.WorkingDirectory);
    new OutputTarget(path, OutputFormat.Png).CheckWritable();

    PreparedRender prepared = RenderCommand.PrepareScene(new RenderRequest(source, settings, given, scriptOptions.Time(parse)));
    SceneTessellation tessellation = SceneExport.Tessellate(prepared);
    foreach (string note in prepared.Notes.Concat(tessellation.Notes))
      env.Error.WriteLine("grcis: note: " + note);

    try
    {
      GltfWriter.Save(tessellation, path, source.DisplayName);
    }
    catch (Exception e) when (e is IOException or UnauthorizedAccessException)
    {
      throw new CliFailure($"cannot write '{path}': {e.Message}", e);
    }

    if (!parse.GetValue(quiet))
    {
      int boxes = tessellation.Parts.Count(p => p.Kind == PartKind.BoundingBox);
      int triangles = tessellation.Parts.Sum(p => p.TriangleCount);
      string bin = GltfWriter.FormatOf(path) == GltfFormat.Json ? $" (+ {Path.GetFileNameWithoutExtension(path)}.bin)" : "";
      env.Out.WriteLine($"wrote {path}{bin}: {tessellation.Parts.Count} solids" + (boxes > 0 ? $" ({boxes} as bounding boxes)" : "") +
                        $", {triangles} triangles, {(tessellation.Camera != null ? "a camera" : "no camera")}, {tessellation.Lights.Count} lights");
    }
    return ExitCodes.Success;
  }

  /// <summary><c>-o</c>: a .glb or .gltf file (default <c>{stem}.glb</c> in the working directory).</summary>
  /// <exception cref="UsageException">An empty name or another extension.</exception>
  static string ResolveOutput(string? o, string stem, string workingDirectory)
  {
    if (o != null && string.IsNullOrWhiteSpace(o))
      throw new UsageException("-o needs a file name (got an empty one); leave -o out for the default name");
    string full = Path.GetFullPath(o ?? stem + ".glb", workingDirectory);
    if (GltfWriter.FormatOf(full) == null)
    {
      string ext = Path.GetExtension(full);
      throw new UsageException(ext.Length == 0
        ? $"output file '{o}' has no extension; use .glb or .gltf"
        : $"cannot export to '{ext}' files ('{o}'); use .glb (binary glTF) or .gltf (JSON and .bin)");
    }
    return full;
  }

  /// <summary><c>--size WxH</c>, given only when the option is.</summary>
  static (RenderSettings Settings, GivenSettings Given) ReadSize(string? text)
  {
    if (text == null)
      return (new RenderSettings(), GivenSettings.None);
    ImageSize s = ImageSize.Parse(text);
    return (new RenderSettings { Width = s.Width, Height = s.Height }, GivenSettings.Size);
  }
}
