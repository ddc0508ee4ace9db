using System;
using System.Collections.Generic;
using System.Linq;
using GrCis.Cli.Animation;
using System.CommandLine;
using System.Globalization;
using System.IO;
using GrCis.Cli.Jobs;
using GrCis.Cli.Output;
using GrCis.Cli.ProgressViews;
using GrCis.Cli.SceneSources;
using GrCis.Cli.Watching;
using GrCis.Scripting;
using Rendering;
using Rendering.Execution;
using Rendering.Parts;
using GrCis.Hosting;

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

  readonly RenderOptionSet render = new();
  readonly MemoryLimitOption memoryLimit = new();

  readonly Option<string?> format = new("--format")
  {
    Description = "png or pfm (linear float); default: from the output file's extension",
  };

  readonly Option<string?> tiles = new("--tiles")
  {
    Description = "Render only part INDEX of COUNT (interleaved tiles) into a .grcis-part file for 'grcis merge'",
    HelpName = "i/n",
  };

  readonly Option<string?> noise = new("--noise")
  {
    Description = "Also write the estimated noise: each pixel's standard error (linear, one-band .pfm; needs 2x2 spp or more)",
    HelpName = "file.pfm",
  };

  readonly Option<bool> quiet = new("--quiet", "-q") { Description = "Print nothing on success: no progress, no summary (notes, warnings and errors still go to stderr)" };
  readonly ScriptOptions scriptOptions = new();
  readonly WatchOption watch = new("the image");

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("render", "Render a still image of a scene")
    {
      scene, output, format, tiles, noise, quiet,
    };
    render.AddTo(cmd);
    memoryLimit.AddTo(cmd);
    scriptOptions.AddTo(cmd);
    watch.AddTo(cmd);
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    // Validate everything before any work so usage errors never leave files behind.
    render.Read(parse);
    memoryLimit.Apply(parse, env);
    if (!watch.IsSet(parse))
      return RenderOnce(parse, env);
    if (parse.GetValue(tiles) != null)
      throw new UsageException("--watch renders the whole image; --tiles is for a render split over processes");
    return WatchOption.Run(env, parse.GetValue(scene), parse.GetValue(scriptOptions.Modules) ?? [], passEnv => RenderOnce(parse, passEnv));
  }

  /// <summary>One render (the whole command, or one pass of <c>--watch</c>).</summary>
  int RenderOnce(ParseResult parse, CliEnvironment env)
  {
    RenderSettings settings = render.Read(parse);
    ShardSpec? part = parse.GetValue(tiles) is string t ? ShardSpec.Parse(t, "--tiles") : null;

    ISceneSource source = scriptOptions.Resolve(parse, parse.GetValue(scene), env);
    using var scriptHost = source as IDisposable;
    OutputTarget target = ResolveTarget(parse, source, part, env);
    target.CheckWritable();
    OutputTarget? noiseTarget = ResolveNoiseTarget(parse, part, target, env);
    noiseTarget?.CheckWritable();

    // Command line, then the script's context values, then the defaults.
    PreparedRender setup = PrepareScene(new RenderRequest(source, settings, render.Given(parse), scriptOptions.Time(parse)));
    settings = setup.Settings;
    MemoryBudget.Check(settings.Size);
    foreach (string note in setup.Notes)
      env.Error.WriteLine("grcis: note: " + note);

    if (setup.Synthesizer == null && settings.SamplesPerPixel > 1 && settings.EffectiveSamplesPerPixel != settings.SamplesPerPixel)
      env.Error.WriteLine($"grcis: note: --spp {settings.SamplesPerPixel} rounded up to {settings.EffectiveSamplesPerPixel} (a square grid)");

    IProgressView view = parse.GetValue(quiet) ? new SilentProgressView()
      : env.Interactive ? new SpectreProgressView(env.Error)
      : new PlainProgressView(env.Error);
    FrameResult result;
    try
    {
      result = view.Run($"render {source.DisplayName}",
        report => setup.Render(report, env.Cancel,
          part is ShardSpec p ? PartLayout.Tiles(settings.Size.Width, settings.Size.Height, p.Index, p.Count) : null));
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

    // Both files or neither: the noise map first, removed again when the image cannot be written.
    if (noiseTarget != null)
    {
      if (result.Statistics.Noise == null)
        env.Error.WriteLine($"grcis: warning: no noise estimate at {result.Statistics.SamplesPerPixel} spp (it needs 2x2 supersampling or more); '{noiseTarget.FullPath}' holds NaN");
      noiseTarget.Save((result.Noise ?? new NoiseImage(result.Image.Width, result.Image.Height)).StandardError(), 1.0);
    }
    try
    {
      if (part is ShardSpec shard)
        target.SavePart(StillPart.Header(source, setup, shard, Modules(parse, env), result.Statistics.SamplesPerPixel), result.Image);
      else
        target.Save(result.Image, settings.Gamma);
    }
    catch (CliFailure) when (noiseTarget != null)
    {
      File.Delete(noiseTarget.FullPath);
      throw;
    }
    if (!parse.GetValue(quiet))
      env.Out.WriteLine(Summary(target, settings, result) + (part is ShardSpec sp ? $", part {sp} (merge with 'grcis merge')" : ""));
    return ExitCodes.Success;
  }

  /// <summary><c>-o</c> and <c>--format</c>; with <c>--tiles</c> the output is a part file (default <c>{stem}-{i}of{n}.grcis-part</c>).</summary>
  OutputTarget ResolveTarget(ParseResult parse, ISceneSource source, ShardSpec? part, CliEnvironment env)
  {
    string? o = parse.GetValue(output);
    if (part is ShardSpec p)
    {
      if (parse.GetValue(format) != null)
        throw new UsageException("--tiles writes a .grcis-part file; --format applies to 'grcis merge'");
      o ??= $"{source.OutputStem}-{p.Index}of{p.Count}{PartFile.Extension}";
    }
    OutputTarget target = OutputTarget.Resolve(o, parse.GetValue(format), source.OutputStem, env.WorkingDirectory);
    if (part != null && target.Format != OutputFormat.Part)
      throw new UsageException($"--tiles writes a part file: name it *{PartFile.Extension} (got '{o}'); 'grcis merge' makes the .png or .pfm");
    if (part == null && target.Format == OutputFormat.Part)
      throw new UsageException($"a {PartFile.Extension} file is written only with --tiles i/n");
    return target;
  }

  /// <summary><c>--noise</c>: a .pfm file beside the image, not with <c>--tiles</c>, not the image itself.</summary>
  OutputTarget? ResolveNoiseTarget(ParseResult parse, ShardSpec? part, OutputTarget image, CliEnvironment env)
  {
    if (parse.GetValue(noise) is not string n)
      return null;
    if (part != null)
      throw new UsageException("--noise is not written with --tiles (a part has no whole image to estimate)");
    OutputTarget target = OutputTarget.Resolve(n, null, "noise", env.WorkingDirectory, "--noise");
    if (target.Format != OutputFormat.Pfm)
      throw new UsageException($"--noise writes linear floats: name it *.pfm (got '{n}')");
    if (string.Equals(target.FullPath, image.FullPath, StringComparison.Ordinal))
      throw new UsageException($"--noise '{n}' is the image's own output file");
    return target;
  }

  IEnumerable<string> Modules(ParseResult parse, CliEnvironment env) =>
    (parse.GetValue(scriptOptions.Modules) ?? []).Select(m => System.IO.Path.GetFullPath(m, env.WorkingDirectory));

  static string Summary(OutputTarget target, RenderSettings s, FrameResult r)
  {
    string line = string.Create(CultureInfo.InvariantCulture,
      $"wrote {target.FullPath}: {s.Size}, spp {r.Statistics.SamplesPerPixel}, seed {s.Seed}, {r.Statistics.Elapsed.TotalSeconds:0.00} s");
    // Rays per second only when the time is long enough to say.
    if (r.Statistics.Elapsed.TotalSeconds > 1e-3 && r.Statistics.Rays > 0)
      line += string.Create(CultureInfo.InvariantCulture, $", {r.Statistics.RaysPerSecond / 1e6:0.00} Mrays/s");
    if (r.Statistics.Noise is double noise)
      line += string.Create(CultureInfo.InvariantCulture, $", noise {noise:0.####} RMSE");
    return line;
  }

  /// <summary>
  /// Builds the scene and applies the precedence rule (command line, then the script's context values, then the
  /// defaults); a script's choice out of range is a failure of the command, worded with the option names.
  /// </summary>
  internal static PreparedRender PrepareScene(RenderRequest request)
  {
    try
    {
      return request.Prepare(CliSettings.OptionName);
    }
    catch (ScriptChoiceException e)
    {
      throw new CliFailure(e.Message);
    }
  }
}
