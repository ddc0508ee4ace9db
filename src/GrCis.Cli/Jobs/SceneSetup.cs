using System;
using System.Collections.Generic;
using GrCis.Cli.SceneSources;
using GrCis.Scripting;
using Rendering;

namespace GrCis.Cli.Jobs;

/// <summary>
/// A scene ready to render with the settings that apply to it. For a scene script the precedence is:
/// an option given on the command line, then the script's context value, then the default. So the
/// script's size and supersampling count unless <c>--size</c> / <c>--spp</c> are given, and its
/// image function (CTX_ALGORITHM) and renderer (CTX_SYNTHESIZER) are used unless an option they
/// cannot honour is given.
/// </summary>
public sealed class SceneSetup
{
  SceneSetup(IRayScene scene, RenderSettings settings)
  {
    Scene = scene;
    Settings = settings;
  }

  public IRayScene Scene { get; }

  /// <summary>Settings after precedence (what the render and its summary line use).</summary>
  public RenderSettings Settings { get; private set; }

  /// <summary>The script's image function (switches given on the command line applied), or null for the default.</summary>
  public IImageFunction? ImageFunction { get; private set; }

  /// <summary>The script's renderer (sized to the image), or null for the default.</summary>
  public ImageSynthesizer? Synthesizer { get; private set; }

  /// <summary>The script run (null for a built-in scene).</summary>
  public ScriptScene? Script { get; private set; }

  /// <summary>Time the scene was set to (null when it does not change with time).</summary>
  public double? Time { get; private set; }

  /// <summary>Things the user should know (an option that replaced a script object, an ignored --time).</summary>
  public List<string> Notes { get; } = new();

  /// <summary>Builds the scene of <paramref name="source"/> and applies the precedence rules.</summary>
  /// <param name="cli">Settings from the command line (defaults where not given).</param>
  /// <param name="given">Which of them the user typed.</param>
  /// <param name="time">The <c>--time</c> value, if given.</param>
  public static SceneSetup Create(ISceneSource source, RenderSettings cli, ExplicitOptions given, double? time)
  {
    ArgumentNullException.ThrowIfNull(source);
    ArgumentNullException.ThrowIfNull(cli);
    if (source is not ScriptSceneSource script)
    {
      var plain = new SceneSetup(source.CreateScene(), cli);
      plain.SetTime(time, null);
      return plain;
    }

    ScriptScene run = script.Load();
    var setup = new SceneSetup(run.Scene, cli) { Script = run };
    setup.ApplyScript(run, cli, given, script.DisplayName);
    setup.SetTime(time, run.Time);
    return setup;
  }

  void ApplyScript(ScriptScene run, RenderSettings cli, ExplicitOptions given, string name)
  {
    RenderSettings s = cli;

    // Size and supersampling: command line, then script, then default.
    if (!given.Size && (run.Width != null || run.Height != null))
    {
      int w = run.Width ?? cli.Size.Width, h = run.Height ?? cli.Size.Height;
      if (w <= 0 || h <= 0 || (long)w * h > Rendering.Imaging.Rgb8Image.MaxPixels)
        throw new CliFailure($"{name}: the script asks for the image size {w}x{h}, which is not a valid size");
      s = s with { Size = new ImageSize(w, h) };
    }
    if (!given.SamplesPerPixel && run.SuperSampling is int spp)
    {
      if (spp < 1 || spp > RenderSettings.MaxSamplesPerPixel)
        throw new CliFailure($"{name}: the script asks for supersampling {spp}; it must be 1 to {RenderSettings.MaxSamplesPerPixel}");
      s = s with { SamplesPerPixel = spp };
    }

    // The script's renderer, unless a sampling option was given.
    if (run.Synthesizer != null)
    {
      if (given.AnySamplingOption)
        Notes.Add($"--spp/--jitter given: the script's renderer {run.Synthesizer.GetType().Name} is not used");
      else if (run.Synthesizer is ImageSynthesizer synth)
      {
        synth.Width = s.Size.Width;
        synth.Height = s.Size.Height;
        Synthesizer = synth;
        if (!given.Gamma)
          s = s with { Gamma = synth.Gamma > 0.001 ? synth.Gamma : 1.0 };
      }
      else
        Notes.Add($"the script's renderer {run.Synthesizer.GetType().Name} is not an ImageSynthesizer; using the default renderer");
    }

    // The script's image function; switches given on the command line apply to it when it is a RayTracing.
    if (run.Algorithm != null)
    {
      if (run.Algorithm is RayCasting rc)
        rc.Accel = s.Accel;   // --accel applies to the script's own ray caster too
      if (run.Algorithm is RayTracing rt)
      {
        if (given.NoShadows) rt.DoShadows = false;
        if (given.NoReflections) rt.DoReflections = false;
        if (given.NoRefractions) rt.DoRefractions = false;
        ImageFunction = rt;
      }
      else if (given.AnyImageFunctionSwitch)
        Notes.Add($"--no-shadows/--no-reflections/--no-refractions given: the script's image function {run.Algorithm.GetType().Name} is replaced by RayTracing");
      else
        ImageFunction = run.Algorithm;
    }

    Settings = s.Validate();
  }

  void SetTime(double? cliTime, double? scriptTime)
  {
    if (Scene is ITimeDependent td && SceneCloner.IsTimeDependent(Scene))
    {
      double t = cliTime ?? scriptTime ?? td.Start;
      td.Time = t;
      Time = td.Time;
      if (cliTime is double c && Time != c)
        Notes.Add($"--time {c} lies outside the animation [{td.Start}, {td.End}]; rendered at {Time}");
    }
    else if (cliTime != null)
      Notes.Add("the scene does not change with time; --time is ignored");
  }
}
