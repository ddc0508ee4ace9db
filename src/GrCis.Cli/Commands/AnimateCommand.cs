using System;
using System.Collections.Generic;
using System.Linq;
using System.CommandLine;
using System.Globalization;
using System.IO;
using GrCis.Cli.Animation;
using GrCis.Cli.Jobs;
using GrCis.Cli.ProgressViews;
using GrCis.Cli.SceneSources;
using GrCis.Scripting;
using GrCis.Hosting;

namespace GrCis.Cli.Commands;

/// <summary>
/// <c>grcis animate scene -o frames/out####.png [--from A] [--to B] [--fps F] [--frames a-b]
/// [--shard i/n] [--resume] [--video out.mp4] [--shutter S] [--parallel auto|frames|tiles]</c>
/// plus the render options: the frames of an animation, each written atomically, resumable and
/// shardable over processes and machines (docs/scale-out.md).
/// </summary>
public sealed class AnimateCommand
{
  readonly Argument<string?> scene = new("scene")
  {
    Description = $"Scene script (*.cs) or built-in scene name (see 'grcis list'); default: \"{SceneResolver.DefaultSceneName}\"",
    Arity = ArgumentArity.ZeroOrOne,
  };

  readonly Option<string?> output = new("--output", "-o")
  {
    Description = "Frame files: #### is the zero-padded frame number (Blender's convention), e.g. frames/out####.png",
    HelpName = "pattern",
  };

  readonly Option<double?> from = new("--from") { Description = "Start time in seconds (default: the script's, else 0)", HelpName = "A" };
  readonly Option<double?> to = new("--to") { Description = "End time in seconds, included (default: the script's, else 10)", HelpName = "B" };
  readonly Option<double?> fps = new("--fps") { Description = "Frames per second (default: the script's, else 25)", HelpName = "F" };

  readonly Option<string?> frames = new("--frames")
  {
    Description = "Only frames a to b (numbers from 0; frame k is at start + k/fps)",
    HelpName = "a-b",
  };

  readonly Option<string?> shard = new("--shard")
  {
    Description = "Render only frames k ≡ i (mod n): one of n processes or machines (i from 0)",
    HelpName = "i/n",
  };

  readonly Option<bool> resume = new("--resume")
  {
    Description = "Skip frames already made by this same render (intact, fingerprint and pixel checksum match); redo the others and say why",
  };

  readonly Option<string?> video = new("--video")
  {
    Description = "Also encode the frames into a video with ffmpeg (e.g. out.mp4)",
    HelpName = "file",
  };

  readonly Option<double> shutter = new("--shutter")
  {
    Description = "Motion blur: the shutter stays open this fraction of a frame (0 = sharp, 1 = a whole frame)",
    HelpName = "S",
    DefaultValueFactory = _ => 0.0,
  };

  readonly Option<string> parallel = new("--parallel")
  {
    Description = "auto: frames in parallel up to 640x480 pixels, else tiles (measured, docs/animation.md); frames: N frames at once, one thread each; tiles: one frame at a time on all threads",
    HelpName = "auto|frames|tiles",
    DefaultValueFactory = _ => "auto",
  };

  readonly Option<bool> quiet = new("--quiet", "-q") { Description = "Print nothing on success: no progress, no summary (notes, warnings and errors still go to stderr)" };

  readonly RenderOptionSet render = new();
  readonly MemoryLimitOption memoryLimit = new();
  readonly ScriptOptions scriptOptions = new();
  readonly WatchOption watch = new("the first frame (or the --frames)");

  public Command Build(CliEnvironment env)
  {
    var cmd = new Command("animate", "Render the frames of an animation (resumable, shardable) and optionally a video")
    {
      scene, output, from, to, fps, frames, shard, resume, video, shutter, parallel,
    };
    render.AddTo(cmd);
    memoryLimit.AddTo(cmd);
    scriptOptions.AddTo(cmd, withTime: false);
    cmd.Options.Add(quiet);
    watch.AddTo(cmd);
    cmd.SetAction(parse => Execute(parse, env));
    return cmd;
  }

  int Execute(ParseResult parse, CliEnvironment env)
  {
    render.Read(parse);
    memoryLimit.Apply(parse, env);
    if (!watch.IsSet(parse))
      return AnimateOnce(parse, env, watching: false);
    if (parse.GetValue(video) != null || parse.GetValue(shard) != null || parse.GetValue(resume))
      throw new UsageException("--watch renders the frames again after each save: --video, --shard and --resume do not apply");
    return WatchOption.Run(env, parse.GetValue(scene), parse.GetValue(scriptOptions.Modules) ?? [], passEnv => AnimateOnce(parse, passEnv, watching: true));
  }

  /// <summary>The frames (the whole command, or one pass of <c>--watch</c>, which renders the first frame unless <c>--frames</c> says otherwise).</summary>
  int AnimateOnce(ParseResult parse, CliEnvironment env, bool watching)
  {
    // Validate everything before any work so usage errors never leave files behind.
    RenderSettings settings = render.Read(parse);
    string? outputText = parse.GetValue(output);
    if (string.IsNullOrWhiteSpace(outputText))
      throw new UsageException("missing -o: give the frame files, e.g. -o frames/out####.png");
    FramePattern pattern = FramePattern.Parse(outputText, env.WorkingDirectory);
    FrameRange? range = parse.GetValue(frames) is string f ? FrameRange.Parse(f) : watching ? new FrameRange(0, 0) : null;
    ShardSpec part = parse.GetValue(shard) is string s ? ShardSpec.Parse(s) : ShardSpec.All;
    ParallelMode requested = ParseParallel(parse.GetValue(parallel) ?? "auto");
    double open = parse.GetValue(shutter);
    if (!(open >= 0.0 && open <= 1.0))
      throw new UsageException($"invalid --shutter {open.ToString(CultureInfo.InvariantCulture)}: must be between 0 (sharp) and 1 (a whole frame)");
    string? videoPath = parse.GetValue(video) is string v ? Path.GetFullPath(v, env.WorkingDirectory) : null;
    if (videoPath != null && part.Count > 1)
      throw new UsageException(
        "--video cannot be combined with --shard: each shard has only some frames; when all shards are done, run the same command once with --resume --video (it renders nothing and encodes)");
    if (videoPath != null && Path.GetExtension(videoPath).Length < 2)
      throw new UsageException($"--video '{parse.GetValue(video)}' has no extension; e.g. out.mp4 (ffmpeg picks the container from it)");

    if (videoPath != null && !Directory.Exists(Path.GetDirectoryName(videoPath)))
      throw new CliFailure($"cannot write video '{videoPath}': directory '{Path.GetDirectoryName(videoPath)}' does not exist");

    ISceneSource source = ResolveScene(env, parse, parse.GetValue(scene));
    using var scriptHost = source as IDisposable;

    // The script runs once (its preprocessing too); every frame renders a clone of its scene.
    // Command line, then the script's context values (size, spp, range, …), then the defaults.
    PreparedRender setup = RenderCommand.PrepareScene(new RenderRequest(source, settings, render.Given(parse))
    {
      Start = parse.GetValue(from),
      End = parse.GetValue(to),
      Fps = parse.GetValue(fps),
    });
    settings = setup.Settings;
    MemoryBudget.Check(settings.Size);
    foreach (string note in setup.Notes)
      env.Error.WriteLine("grcis: note: " + note);
    AnimationPlan plan = AnimationPlan.Create(parse.GetValue(from), parse.GetValue(to), parse.GetValue(fps), setup.Timing, setup.Scene, range, part);

    if (setup.Synthesizer == null && settings.SamplesPerPixel > 1 && settings.EffectiveSamplesPerPixel != settings.SamplesPerPixel)
      env.Error.WriteLine($"grcis: note: --spp {settings.SamplesPerPixel} rounded up to {settings.EffectiveSamplesPerPixel} (a square grid)");

    var fingerprint = FrameFingerprint.Of(source, setup, Modules(parse, env), plan.Timeline, open);
    var store = new FrameStore(pattern, settings.Size, settings.Gamma, fingerprint);
    store.Prepare();
    var todo = new System.Collections.Generic.List<int>(plan.Frames.Count);
    var found = new ResumeReport();
    bool resuming = parse.GetValue(resume);
    foreach (int k in plan.Frames)
    {
      store.RemoveStaleTemporaries(k);
      FrameCheck check = resuming ? store.Check(k) : FrameCheck.Missing;
      found.Add(pattern.FileOf(k), check);
      if (check.State != FrameState.Kept)
        todo.Add(k);
    }
    int skipped = plan.Frames.Count - todo.Count;
    if (found.Redone > 0)
      env.Error.WriteLine("grcis: note: --resume is " + found.Describe("redoing"));

    var renderer = new FrameRenderer(setup.Scene, setup.Plan, plan.Timeline, open);
    foreach (string note in renderer.Parts.Notes())
      env.Error.WriteLine("grcis: note: " + note);
    if (open > 0.0 && (!renderer.IsAnimated || renderer.Sequential))
      env.Error.WriteLine("grcis: note: --shutter has no effect: " +
        (renderer.Sequential ? "the script's own image function renders its scene at one time per frame" : "nothing in this scene moves"));
    int threads = settings.EffectiveThreads;
    ParallelMode mode = renderer.Sequential ? ParallelMode.Tiles : FrameScheduler.Choose(requested, settings.Size, threads, todo.Count);
    var scheduler = new FrameScheduler(renderer, store);

    IAnimationProgressView view = parse.GetValue(quiet) ? new SilentAnimationProgressView()
      : env.Interactive ? new SpectreAnimationProgressView(env.Error)
      : new PlainAnimationProgressView(env.Error);
    var clock = System.Diagnostics.Stopwatch.StartNew();
    int saved;
    try
    {
      saved = view.Run($"animate {source.DisplayName}", plan.Frames.Count, skipped, report =>
      {
        int done = skipped, rendered = 0;
        return scheduler.Run(todo, mode, threads, k =>
        {
          done++;
          rendered++;
          report(new AnimationProgress(done, plan.Frames.Count, rendered, clock.Elapsed, k));
        }, env.Cancel);
      });
    }
    catch (Exception e) when (source is ScriptSceneSource script && script.WithScriptLine(e.InnerException ?? e) is ScriptRuntimeException located)
    {
      // A class declared in the script (texture, camera, solid) threw while rendering: name its line.
      throw located;
    }
    clock.Stop();

    if (env.Cancel.IsCancellationRequested)
    {
      env.Error.WriteLine($"grcis: error: cancelled after {saved} new frames; run again with --resume to continue");
      return ExitCodes.Cancelled;
    }

    bool silent = parse.GetValue(quiet);
    if (!silent)
    {
      env.Out.WriteLine(Summary(pattern, plan, saved, skipped, mode, threads, clock.Elapsed));
      if (found.Redone > 0)
        env.Out.WriteLine(found.Describe("redid"));
    }

    if (videoPath != null)
    {
      VideoEncoder? encoder = VideoEncoder.Find();
      if (encoder == null)
      {
        // The frames are done and kept; the missing video still fails the job so a batch run notices.
        env.Error.WriteLine($"grcis: error: {VideoEncoder.MissingMessage()}; the frames are kept in '{pattern.Directory}'");
        return ExitCodes.Failure;
      }
      encoder.Encode(pattern, plan.Range.First, plan.Range.Count, plan.Timeline.Fps, videoPath);
      if (!silent)
        env.Out.WriteLine(string.Create(CultureInfo.InvariantCulture,
          $"wrote {videoPath}: frames {plan.Range} at {plan.Timeline.Fps:0.###} fps"));
    }
    return ExitCodes.Success;
  }

  IEnumerable<string> Modules(ParseResult parse, CliEnvironment env) =>
    (parse.GetValue(scriptOptions.Modules) ?? []).Select(m => Path.GetFullPath(m, env.WorkingDirectory));

  ISceneSource ResolveScene(CliEnvironment env, ParseResult parse, string? spec)
  {
    if (spec != null && env.ExtraScenes?.Invoke(spec) is ISceneSource extra)
      return extra;
    return scriptOptions.Resolve(parse, spec, env);
  }

  static ParallelMode ParseParallel(string text) => text.Trim().ToLowerInvariant() switch
  {
    "auto" => ParallelMode.Auto,
    "frames" => ParallelMode.Frames,
    "tiles" => ParallelMode.Tiles,
    _ => throw new UsageException($"invalid --parallel '{text}': use auto, frames or tiles"),
  };

  static string Summary(FramePattern pattern, AnimationPlan plan, int saved, int skipped, ParallelMode mode, int threads, TimeSpan elapsed)
  {
    double rate = saved > 0 && elapsed.TotalSeconds > 0 ? saved / elapsed.TotalSeconds : 0.0;
    string shardText = plan.Shard.Count > 1 ? $", shard {plan.Shard}" : "";
    string skippedText = skipped > 0 ? $" ({skipped} complete, skipped)" : "";
    return string.Create(CultureInfo.InvariantCulture,
      $"wrote {saved} frame{(saved == 1 ? "" : "s")}{skippedText} to {pattern.FullPattern}: frames {plan.Range}{shardText} of 0-{plan.Timeline.FrameCount - 1}, " +
      $"{elapsed.TotalSeconds:0.00} s, {rate:0.00} frames/s, parallel {mode.ToString().ToLowerInvariant()} on {threads} thread{(threads == 1 ? "" : "s")}");
  }
}
