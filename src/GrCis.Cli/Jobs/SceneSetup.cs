using System;
using System.Collections.Generic;
using GrCis.Cli.SceneSources;
using GrCis.Scripting;
using GrCis.Hosting;
using Rendering;

namespace GrCis.Cli.Jobs;

/// <summary>
/// A scene ready to render with the settings that apply to it. For a scene script the precedence is
/// the shared rule of every front end (<see cref="Precedence"/>): an option given on the command line,
/// then the script's context value, then the default.
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

  /// <summary>Builds the scene of <paramref name="source"/> and applies the precedence rule (<see cref="Precedence"/>).</summary>
  /// <param name="cli">Settings from the command line (defaults where not given).</param>
  /// <param name="given">Which of them the user typed.</param>
  /// <param name="time">The <c>--time</c> value, if given.</param>
  public static SceneSetup Create(ISceneSource source, RenderSettings cli, GivenSettings given, double? time)
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
    var choices = new ScriptChoices
    {
      Name = script.DisplayName,
      Width = run.Width,
      Height = run.Height,
      SamplesPerPixel = run.SuperSampling,
      ImageFunction = run.Algorithm,
      Renderer = run.Synthesizer,
    };
    RenderPlan plan;
    try
    {
      plan = Precedence.Resolve(cli, given, choices, CliSettings.OptionName);
    }
    catch (ScriptChoiceException e)
    {
      throw new CliFailure(e.Message);
    }
    setup.Settings = plan.Settings;
    setup.ImageFunction = plan.ImageFunction;
    setup.Synthesizer = plan.Synthesizer;
    setup.Notes.AddRange(plan.Notes);
    setup.SetTime(time, run.Time);
    return setup;
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
