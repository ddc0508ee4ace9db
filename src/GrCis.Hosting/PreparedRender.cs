using System;
using System.Collections.Generic;
using System.Threading;
using GrCis.Scripting;
using Rendering;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// A scene ready to render with the settings that apply to it, as every front end prepares it: the
/// scene built, the shared precedence rule applied (<see cref="Precedence"/>: a setting the user gave,
/// then the script's context value, then the default) and the scene set to its time. <see cref="Render"/>
/// renders it with the one frame renderer (<see cref="FrameRendering"/>).
/// </summary>
public sealed class PreparedRender
{
  PreparedRender(IRayScene scene, RenderPlan plan, ScriptScene? script)
  {
    Scene = scene;
    Plan = plan;
    Settings = plan.Settings;
    ImageFunction = plan.ImageFunction;
    Synthesizer = plan.Synthesizer;
    Script = script;
    Notes.AddRange(plan.Notes);
  }

  public IRayScene Scene { get; }

  /// <summary>What precedence decided; builds the image function, the sampler and the options of this render.</summary>
  public RenderPlan Plan { get; }

  /// <summary>Settings after precedence (what the render and its summary line use).</summary>
  public RenderSettings Settings { get; }

  /// <summary>The script's image function (given switches applied), or null for the settings' ray tracer.</summary>
  public IImageFunction? ImageFunction { get; }

  /// <summary>The script's renderer (sized to the image), or null for the settings' sampler.</summary>
  public ImageSynthesizer? Synthesizer { get; }

  /// <summary>The script run (null for a built-in scene).</summary>
  public ScriptScene? Script { get; }

  /// <summary>Time the scene was set to (null when it does not change with time).</summary>
  public double? Time { get; private set; }

  /// <summary>The animation range the scene asks for: the script's context values, else the source's, else null.</summary>
  public ISceneTiming? Timing { get; private init; }

  /// <summary>Things the user should know (a setting that replaced a script object, an ignored time).</summary>
  public List<string> Notes { get; } = new();

  /// <summary>Builds the scene of <paramref name="request"/> and applies the precedence rule.</summary>
  /// <exception cref="ScriptChoiceException">The script asks for an image size or sample count out of range.</exception>
  internal static PreparedRender Create(RenderRequest request, Func<Setting, string>? name)
  {
    ArgumentNullException.ThrowIfNull(request);
    if (request.Source is not ScriptSceneSource script)
    {
      var plain = new PreparedRender(request.Source.CreateScene(), Precedence.Resolve(request.Settings, request.Given, null, name), null)
      {
        Timing = request.Source as ISceneTiming,
      };
      plain.SetTime(request.Time, null, name);
      return plain;
    }

    ScriptScene run = script.Load(request.ScriptContext);
    var choices = new ScriptChoices
    {
      Name = script.DisplayName,
      Width = run.Width,
      Height = run.Height,
      SamplesPerPixel = run.SuperSampling,
      ImageFunction = run.Algorithm,
      Renderer = run.Synthesizer,
    };
    RenderPlan plan = Precedence.Resolve(request.Settings, request.Given, choices, name);
    ScriptObjects.Wire(plan.ImageFunction, run.Scene);
    var setup = new PreparedRender(run.Scene, plan, run)
    {
      Timing = new ScriptTiming(run.Start, run.End, run.Fps),
    };
    setup.SetTime(request.Time, run.Time, name);
    return setup;
  }

  void SetTime(double? given, double? scriptTime, Func<Setting, string>? name)
  {
    string option = name?.Invoke(Setting.Time) ?? "the time";
    if (Scene is ITimeDependent td && SceneCloner.IsTimeDependent(Scene))
    {
      double t = given ?? scriptTime ?? td.Start;
      td.Time = t;
      Time = td.Time;
      if (given is double c && Time != c)
        Notes.Add(FormattableString.Invariant($"{option} {c} lies outside the animation [{td.Start}, {td.End}]; rendered at {Time}"));
    }
    else if (given != null)
      Notes.Add($"the scene does not change with time; {option} is ignored");
  }

  /// <summary>Renders the prepared scene (only <paramref name="tiles"/>, when given: one part of a scaled-out still).</summary>
  /// <param name="context">Where the rays go (an observer); null = a fresh context, counts only.</param>
  /// <exception cref="RenderException">The scene's code failed.</exception>
  public FrameResult Render(Action<RenderProgress>? progress = null, CancellationToken cancel = default,
                            IReadOnlyList<Tile>? tiles = null, RenderContext? context = null)
  {
    return FrameRendering.Render(Scene, Plan.CreateImageFunction(Scene), Plan.CreateSynthesizer(), Plan.CreateOptions(tiles: tiles),
      progress, cancel, context);
  }

  sealed record ScriptTiming(double? Start, double? End, double? Fps) : ISceneTiming;
}
