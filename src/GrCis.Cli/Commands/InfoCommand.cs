using System;
using System.CommandLine;
using System.Globalization;
using GrCis.Cli.Jobs;
using GrCis.Cli.SceneSources;
using GrCis.Scripting;
using Rendering;
using GrCis.Hosting;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis info scene.cs [--param …] [--module DIR]…</c> or <c>grcis info "Five balls"</c>: what a
/// scene declares — parameter tooltip, image size, supersampling, animation range, image function
/// and renderer — each with where the value comes from (script or default). Renders nothing.
/// </summary>
public sealed class InfoCommand
{
  readonly Argument<string?> scene = new("scene")
  {
    Description = $"Built-in scene name or a scene script (*.cs); default: \"{SceneResolver.DefaultSceneName}\"",
    Arity = ArgumentArity.ZeroOrOne,
  };

  readonly ScriptOptions scriptOptions = new();

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("info", "Show a scene's parameters tooltip, size, supersampling and animation range") { scene };
    scriptOptions.AddTo(cmd, withTime: false);
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    ISceneSource source = scriptOptions.Resolve(parse, parse.GetValue(scene), env);
    using var scriptHost = source as IDisposable;
    var defaults = new RenderSettings();
    var o = env.Out;

    if (source is BuiltInSceneSource builtIn)
    {
      IRayScene sc = builtIn.CreateScene();
      Line(o, "scene", $"{builtIn.DisplayName} (built-in)");
      Line(o, "parameters", builtIn.ToolTip ?? "(none)");
      Line(o, "size", $"{defaults.Size} (default)");
      Line(o, "supersampling", $"{defaults.SamplesPerPixel} (default)");
      Line(o, "animation", "none (a still scene)");
      Line(o, "algorithm", $"{nameof(RayTracing)} (default)");
      Line(o, "synthesizer", $"{nameof(SimpleImageSynthesizer)} (default; {nameof(SupersamplingImageSynthesizer)} with --spp > 1)");
      Line(o, "lights", (sc.Sources?.Count ?? 0).ToString(CultureInfo.InvariantCulture));
      return ExitCodes.Success;
    }

    var script = (ScriptSceneSource)source;
    ScriptScene run = script.Load();
    Line(o, "scene", script.Path);
    Line(o, "parameters", run.ToolTip ?? "(no tooltip)");
    if (script.Param.Length > 0)
      Line(o, "param", script.Param);
    Line(o, "size", run.Width != null || run.Height != null
      ? $"{run.Width ?? defaults.Size.Width}x{run.Height ?? defaults.Size.Height} (script)"
      : $"{defaults.Size} (default)");
    Line(o, "supersampling", run.SuperSampling is int ss ? $"{ss} (script)" : $"{defaults.SamplesPerPixel} (default)");
    Line(o, "animation", Animation(run));
    Line(o, "algorithm", run.Algorithm != null ? $"{run.Algorithm.GetType().Name} (script)" : $"{nameof(RayTracing)} (default)");
    Line(o, "synthesizer", run.Synthesizer != null
      ? $"{run.Synthesizer.GetType().Name} (script)"
      : $"{nameof(SimpleImageSynthesizer)} (default; {nameof(SupersamplingImageSynthesizer)} with supersampling > 1)");
    Line(o, "lights", (run.Scene.Sources?.Count ?? 0).ToString(CultureInfo.InvariantCulture));
    Line(o, "preprocessing", run.Preprocessed ? "ran (the script was called twice)" : "no");
    return ExitCodes.Success;
  }

  /// <summary>
  /// "start 0 s, end 4 s, 12 fps, 49 frames": the range <c>grcis animate</c> renders without options
  /// (<see cref="AnimationRange.Resolve"/>: the script's context, else its animated scene, else the defaults).
  /// </summary>
  static string Animation(ScriptScene run)
  {
    bool animated = SceneCloner.IsTimeDependent(run.Scene);
    if (run.Start == null && run.End == null && run.Fps == null && !animated)
      return "none (a still scene)";
    (double start, double end, double fps) = AnimationRange.Resolve(null, null, null, new Timing(run.Start, run.End, run.Fps), run.Scene);
    string fpsSource = run.Fps != null ? "" : " (default)";
    string frames;
    try
    {
      frames = new AnimationTimeline(start, end, fps).FrameCount.ToString(CultureInfo.InvariantCulture) + " frames";
    }
    catch (ArgumentOutOfRangeException e)
    {
      frames = "invalid range: " + e.Message.Split('\n')[0].Trim();
    }
    return string.Create(CultureInfo.InvariantCulture, $"start {start} s, end {end} s, {fps} fps{fpsSource}, {frames}");
  }

  sealed record Timing(double? Start, double? End, double? Fps) : ISceneTiming;

  static void Line(System.IO.TextWriter o, string key, string value) => o.WriteLine($"{key + ":",-15}{value}");
}
