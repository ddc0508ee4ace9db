using System;
using System.CommandLine;
using System.Globalization;
using GrCis.Cli.Jobs;
using GrCis.Cli.Output;
using GrCis.Cli.ProgressViews;
using GrCis.Cli.SceneSources;
using GrCis.Scripting;
using Rendering;

namespace GrCis.Cli.Commands;

/// <summary><c>grcis render [scene] -o out.png [--size WxH] [--spp N] …</c>: one still image.</summary>
public sealed class RenderCommand
{
  readonly Argument<string?> scene = new("scene")
  {
    Description = $"Built-in scene name (see 'grcis list') or a scene script (*.cs); default: \"{SceneResolver.DefaultSceneName}\"",
    Arity = ArgumentArity.ZeroOrOne,
  };

  readonly Option<string?> output = new("--output", "-o")
  {
    Description = "Output file (.png or .pfm); default: <scene-name>.png in the current directory",
    HelpName = "file",
  };

  readonly Option<string> size = new("--size", "-s")
  {
    Description = "Image size WIDTHxHEIGHT",
    HelpName = "WxH",
    DefaultValueFactory = _ => ImageSize.Default.ToString(),
  };

  readonly Option<int> spp = new("--spp")
  {
    Description = "Samples per pixel: 1 = pixel centre, N > 1 = jittered n×n grid (rounded up to a square)",
    DefaultValueFactory = _ => 1,
  };

  readonly Option<double> jitter = new("--jitter")
  {
    Description = "Jitter of supersamples within their cell, 0 to 1",
    DefaultValueFactory = _ => 1.0,
  };

  readonly Option<int> threads = new("--threads", "-t")
  {
    Description = "Worker threads; 0 = one per processor",
    DefaultValueFactory = _ => 0,
  };

  readonly Option<long> seed = new("--seed")
  {
    Description = "Seed of all sampling randomness (same seed ⇒ same image on any thread count)",
    DefaultValueFactory = _ => 0L,
  };

  readonly Option<double> gamma = new("--gamma")
  {
    Description = "Display gamma of the PNG (1 = linear)",
    DefaultValueFactory = _ => 2.2,
  };

  readonly Option<string?> format = new("--format")
  {
    Description = "png or pfm (linear float); default: from the output file's extension",
  };

  readonly Option<bool> noShadows = new("--no-shadows") { Description = "Do not cast shadow rays" };
  readonly Option<bool> noReflections = new("--no-reflections") { Description = "Do not trace reflected rays" };
  readonly Option<bool> noRefractions = new("--no-refractions") { Description = "Do not trace refracted rays" };
  readonly Option<bool> quiet = new("--quiet", "-q") { Description = "No progress output" };
  readonly ScriptOptions scriptOptions = new();
  readonly Option<string> accel = AccelOption.Create();

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("render", "Render a still image of a scene")
    {
      scene, output, size, spp, jitter, threads, seed, gamma, format,
      noShadows, noReflections, noRefractions, quiet, accel,
    };
    scriptOptions.AddTo(cmd);
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    // Validate everything before any work so usage errors never leave files behind.
    RenderSettings settings = new RenderSettings
    {
      Size = ImageSize.Parse(parse.GetValue(size) ?? ImageSize.Default.ToString()),
      SamplesPerPixel = parse.GetValue(spp),
      Jitter = parse.GetValue(jitter),
      Threads = parse.GetValue(threads),
      Seed = parse.GetValue(seed),
      Gamma = parse.GetValue(gamma),
      Shadows = !parse.GetValue(noShadows),
      Reflections = !parse.GetValue(noReflections),
      Refractions = !parse.GetValue(noRefractions),
      Accel = AccelOption.Parse(parse.GetValue(accel)),
    }.Validate();

    ISceneSource source = scriptOptions.Resolve(parse, parse.GetValue(scene), env);
    using var scriptHost = source as IDisposable;
    OutputTarget target = OutputTarget.Resolve(parse.GetValue(output), parse.GetValue(format), source.OutputStem, env.WorkingDirectory);
    target.CheckWritable();

    // Command line, then the script's context values, then the defaults.
    SceneSetup setup = SceneSetup.Create(source, settings, Given(parse), scriptOptions.Time(parse));
    settings = setup.Settings;
    foreach (string note in setup.Notes)
      env.Error.WriteLine("grcis: note: " + note);

    if (setup.Synthesizer == null && settings.SamplesPerPixel > 1 && settings.EffectiveSamplesPerPixel != settings.SamplesPerPixel)
      env.Error.WriteLine($"grcis: note: --spp {settings.SamplesPerPixel} rounded up to {settings.EffectiveSamplesPerPixel} (a square grid)");

    IRayScene sc = setup.Scene;
    IProgressView view = parse.GetValue(quiet) ? new SilentProgressView()
      : env.Interactive ? new SpectreProgressView(env.Error)
      : new PlainProgressView(env.Error);
    RenderResult result;
    try
    {
      result = view.Run($"render {source.DisplayName}",
        report => RenderJob.Run(sc, settings, setup.ImageFunction, setup.Synthesizer, report, env.Cancel));
    }
    catch (Exception e) when (source is ScriptSceneSource script && script.WithScriptLine(e.InnerException ?? e) is ScriptRuntimeException located)
    {
      // A class declared in the script (texture, camera, solid) threw while rendering: name its line.
      throw located;
    }

    if (result.Cancelled)
    {
      env.Error.WriteLine($"grcis: error: cancelled; '{target.FullPath}' not written");
      return ExitCodes.Cancelled;
    }

    target.Save(result.Image, settings.Gamma);
    env.Out.WriteLine(Summary(target, settings, result));
    return ExitCodes.Success;
  }

  ExplicitOptions Given(ParseResult parse) => new(
    Size: IsGiven(parse, size),
    SamplesPerPixel: IsGiven(parse, spp),
    Jitter: IsGiven(parse, jitter),
    Gamma: IsGiven(parse, gamma),
    NoShadows: parse.GetValue(noShadows),
    NoReflections: parse.GetValue(noReflections),
    NoRefractions: parse.GetValue(noRefractions));

  static bool IsGiven(ParseResult parse, Option option) => parse.GetResult(option) is { Implicit: false };

  static string Summary(OutputTarget target, RenderSettings s, RenderResult r)
  {
    string line = string.Create(CultureInfo.InvariantCulture,
      $"wrote {target.FullPath}: {s.Size}, spp {r.SamplesPerPixel}, seed {s.Seed}, {r.Elapsed.TotalSeconds:0.00} s");
    if (r.RaysPerSecond is double rps)
      line += string.Create(CultureInfo.InvariantCulture, $", {rps / 1e6:0.00} Mrays/s");
    return line;
  }
}
