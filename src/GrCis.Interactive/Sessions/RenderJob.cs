using System;
using Rendering;
using Rendering.Execution;

namespace GrCis.Interactive;

/// <summary>
/// Everything one render needs, resolved: the scene, the image function and renderer configured
/// from <see cref="RenderSettings"/> (or chosen by the script), and the execution options.
/// Rendering a job with <see cref="TileRenderer"/> gives the image <c>grcis render</c> gives.
/// </summary>
public sealed class RenderJob
{
  RenderJob(IRayScene scene, IImageFunction function, ImageSynthesizer renderer, RenderSettings settings, string? name, string param)
  {
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

  public string? SceneName { get; }

  public string Param { get; }

  public int Width => Settings.Width;

  public int Height => Settings.Height;

  public RenderOptions Options => Settings.ToRenderOptions();

  /// <summary>The image function the settings select: Whitted ray tracing with the three switches.</summary>
  public static RayTracing CreateImageFunction(IRayScene scene, RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(settings);
    // Unbound: it shades MT.scene, so each render worker uses its own clone of an animated scene.
    return RenderSetup.CreateRayTracing(null, settings.Shadows, settings.Reflections, settings.Refractions);
  }

  /// <summary>The renderer the settings select: one centred sample, or n×n (jittered) supersampling.</summary>
  public static ImageSynthesizer CreateRenderer(RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(settings);
    return RenderSetup.CreateSynthesizer(settings.Width, settings.Height, settings.SamplesPerPixel, settings.Jittering, settings.Gamma);
  }

  /// <summary>A job for <paramref name="scene"/>; <paramref name="function"/> and <paramref name="renderer"/> default from the settings.</summary>
  public static RenderJob Create(IRayScene scene, RenderSettings settings, IImageFunction? function = null, IRenderer? renderer = null,
    string? sceneName = null, string param = "")
  {
    ArgumentNullException.ThrowIfNull(scene);
    ArgumentNullException.ThrowIfNull(settings);
    settings.Validate();

    if (settings.Time is double t)
      SceneTime.Set(scene, t);

    if (function == null)
      function = CreateImageFunction(scene, settings);
    else if (function is RayTracing rt)
      ApplySwitches(rt, settings); // the demo's switches apply to a script's ray tracer too, as in GrCis

    ImageSynthesizer synth;
    if (renderer == null)
      synth = CreateRenderer(settings);
    else
    {
      synth = renderer as ImageSynthesizer
        ?? throw new SceneEvaluationException($"The script's renderer {renderer.GetType().Name} is not an ImageSynthesizer; the tile renderer cannot drive it.");
      synth.Width = settings.Width;
      synth.Height = settings.Height;
    }

    // What TileRenderer does at the start of a render; done here too so probes work before any render.
    synth.ImageFunction = function;
    IRayScene? callerScene = MT.scene;
    MT.scene = scene; // an unbound function reaches the camera through MT.scene
    try
    {
      function.Width = settings.Width;
      function.Height = settings.Height;
    }
    finally
    {
      MT.scene = callerScene;
    }
    return new RenderJob(scene, function, synth, settings, sceneName, param);
  }

  /// <summary>A job for a built scene: the script's overrides and its chosen function/renderer win.</summary>
  public static RenderJob Create(BuiltScene built, RenderSettings settings)
  {
    ArgumentNullException.ThrowIfNull(built);
    return Create(built.Scene, settings.With(built.Overrides), built.ImageFunction, built.Renderer, built.Entry.Name, built.Param);
  }

  static void ApplySwitches(RayTracing rt, RenderSettings s) =>
    RenderSetup.ApplySwitches(rt, s.Shadows, s.Reflections, s.Refractions);
}
