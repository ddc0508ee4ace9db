using System;
using Rendering;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// Everything one render needs, resolved: the scene, the image function and renderer configured
/// from <see cref="RenderSettings"/> (or chosen by the script), and the execution options.
/// Rendering a job with <see cref="TileRenderer"/> gives the image <c>grcis render</c> gives.
/// </summary>
public sealed class RenderJob
{
  RenderJob(IRayScene scene, IImageFunction function, ImageSynthesizer renderer, RenderSettings settings, RenderPlan plan, string? name, string param)
  {
    Plan = plan;
    Scene = scene;
    ImageFunction = function;
    Renderer = renderer;
    Settings = settings;
    SceneName = name;
    Param = param;
  }

  public IRayScene Scene { get; }

  public IImageFunction ImageFunction { get; }

  public ImageSynthesizer Renderer { get; }

  /// <summary>The effective settings (script overrides applied).</summary>
  public RenderSettings Settings { get; }

  /// <summary>What precedence decided, the builder of this job's function, renderer and options.</summary>
  public RenderPlan Plan { get; }

  public string? SceneName { get; }

  public string Param { get; }

  /// <summary>
  /// Names the place in the user's code (script or module file and line) of an exception thrown while
  /// rendering, or returns null when none of its frames is there (see <c>ScriptSceneSource.WithScriptLine</c>).
  /// </summary>
  public Func<Exception, Exception?>? LocateError { get; init; }

  public int Width => Settings.Width;

  public int Height => Settings.Height;

  /// <summary>The execution options, from the same builder as every front end's (<see cref="RenderPlan.CreateOptions"/>).</summary>
  public RenderOptions Options => Plan.CreateOptions();

  /// <summary>
  /// What a demo user sets explicitly, winning over a script (<see cref="Precedence"/>): the ray-tracing switches,
  /// whose check boxes apply to a script's ray tracer as in GrCis. Size and sampling are the script's when it sets them.
  /// </summary>
  public const GivenSettings Given = GivenSettings.Switches;

  /// <summary>The image function the settings select: Whitted ray tracing with the three switches.</summary>
  public static RayTracing CreateImageFunction(IRayScene scene, RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(settings);
    // Unbound: it shades MT.scene, so each render worker uses its own clone of an animated scene.
    return settings.CreateImageFunction(null);
  }

  /// <summary>The renderer the settings select: one centred sample, or n×n (jittered) supersampling.</summary>
  public static ImageSynthesizer CreateRenderer(RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(settings);
    return settings.CreateSynthesizer();
  }

  /// <summary>
  /// A job for <paramref name="scene"/>: the script's <paramref name="overrides"/>, <paramref name="function"/> and
  /// <paramref name="renderer"/> (null = not chosen) resolved against <paramref name="settings"/> by the shared precedence rule.
  /// </summary>
  /// <param name="choices">What the script chose through its context (size, supersampling; its function and
  /// renderer when <paramref name="function"/>/<paramref name="renderer"/> are null); null = nothing.</param>
  /// <param name="given">Which of <paramref name="settings"/> win over the script's choices; the demo's <see cref="Given"/>
  /// unless a front end marks more (a chosen algorithm, as <c>grcis render --algorithm</c>).</param>
  /// <exception cref="ScriptChoiceException">The script asks for an image size or supersampling out of range.</exception>
  /// <exception cref="InvalidSettingException">A setting out of range.</exception>
  public static RenderJob Create(IRayScene scene, RenderSettings settings, IImageFunction? function = null, IRenderer? renderer = null,
    string? sceneName = null, string param = "", ScriptChoices? choices = null, GivenSettings given = Given)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(settings);
    choices = (choices ?? new ScriptChoices()) with
    {
      Name = sceneName ?? (choices != null ? choices.Name : "the scene"),
      ImageFunction = function ?? choices?.ImageFunction,
      Renderer = renderer ?? choices?.Renderer,
    };
    RenderPlan plan = Precedence.Resolve(settings, given, choices);
    settings = plan.Settings;

    if (settings.Time is double t)
      SceneTime.Set(scene, t);

    IImageFunction f = plan.CreateImageFunction();   // unbound when from the settings (see CreateImageFunction)
    ScriptObjects.Wire(f, scene);
    ImageSynthesizer synth = plan.CreateSynthesizer();
    Bind(scene, f, synth, settings);
    return new RenderJob(scene, f, synth, settings, plan, sceneName, param) { Notes = plan.Notes };
  }

  /// <summary>
  /// A job for a scene prepared as every front end prepares it (<see cref="RenderRequest.Prepare"/>: built, the one
  /// precedence rule applied, set to its time), so a window or a page renders what <c>grcis render</c> renders.
  /// </summary>
  public static RenderJob From(PreparedRender prepared, string? sceneName = null, string param = "")
  {
    ArgumentNullException.ThrowIfNull(prepared);
    RenderSettings settings = prepared.Settings with { Time = prepared.Time };
    IImageFunction f = prepared.Plan.CreateImageFunction();   // unbound (see CreateImageFunction)
    ImageSynthesizer synth = prepared.Plan.CreateSynthesizer();
    Bind(prepared.Scene, f, synth, settings);
    return new RenderJob(prepared.Scene, f, synth, settings, prepared.Plan, sceneName ?? prepared.Script?.Script.Path, param)
    {
      Notes = prepared.Notes.ToArray(),
      Prepared = prepared,
      // A class of the script that throws while rendering is named with its line, as grcis render names it.
      LocateError = prepared.Script is { } run ? e => run.Script.FindScriptLine(e) : null,
    };
  }

  // What TileRenderer does at the start of a render; done here too so probes work before any render.
  static void Bind(IRayScene scene, IImageFunction f, ImageSynthesizer synth, RenderSettings settings)
  {
    synth.ImageFunction = f;
    IRayScene? callerScene = MT.scene;
    MT.scene = scene; // an unbound function reaches the camera through MT.scene
    try
    {
      f.Width = settings.Width;
      f.Height = settings.Height;
    }
    finally
    {
      MT.scene = callerScene;
    }
  }

  /// <summary>The prepared scene this job was made from (<see cref="From"/>), or null.</summary>
  public PreparedRender? Prepared { get; private init; }

  /// <summary>Things the user should know about how the script's choices were used (<see cref="RenderPlan.Notes"/>).</summary>
  public System.Collections.Generic.IReadOnlyList<string> Notes { get; private init; } = Array.Empty<string>();
}
