using System;
using System.Collections.Generic;
using Rendering;

namespace GrCis.Hosting;

/// <summary>
/// The one precedence rule of every front end: a setting the user gave explicitly, then the scene script's
/// choice, then the default. So a script's size and supersampling count unless the user gave them; its
/// renderer (CTX_SYNTHESIZER) is used unless a sampling setting was given; its image function (CTX_ALGORITHM)
/// is used with the given switches applied, and replaced by ray tracing only when a given switch turns
/// off something a function of another class cannot be told to skip.
/// </summary>
public static class Precedence
{
  /// <summary>Resolves <paramref name="requested"/> (given ones marked in <paramref name="given"/>) against the script's choices.</summary>
  /// <param name="name">How the front end names a setting in notes (an option such as <c>--spp</c>); null = plain words.</param>
  /// <exception cref="ScriptChoiceException">The script asks for an image size or a sample count out of range.</exception>
  /// <exception cref="InvalidSettingException">A requested setting out of range.</exception>
  public static RenderPlan Resolve(RenderSettings requested, GivenSettings given, ScriptChoices? script, Func<Setting, string>? name = null)
  {
    ArgumentNullException.ThrowIfNull(requested);
    name ??= Words;
    if (script == null)
    {
      var plain = new List<string>();
      AddIgnoredSwitches(plain, requested, given, null, name);
      return new RenderPlan(requested.Validate(), null, null, plain);
    }

    RenderSettings s = requested;
    var notes = new List<string>();

    if (!given.HasFlag(GivenSettings.Size) && (script.Width != null || script.Height != null))
    {
      int w = script.Width ?? s.Width, h = script.Height ?? s.Height;
      if (w <= 0 || h <= 0 || (long)w * h > Rendering.Imaging.Rgb8Image.MaxPixels)
        throw new ScriptChoiceException($"{script.Name}: the script asks for the image size {w}x{h}, which is not a valid size");
      s = s with { Width = w, Height = h };
    }
    if (!given.HasFlag(GivenSettings.SamplesPerPixel) && script.SamplesPerPixel is int spp)
    {
      if (spp < 1 || spp > RenderSettings.MaxSamplesPerPixel)
        throw new ScriptChoiceException($"{script.Name}: the script asks for supersampling {spp}; it must be 1 to {RenderSettings.MaxSamplesPerPixel}");
      s = s with { SamplesPerPixel = spp };
    }
    if (!given.HasFlag(GivenSettings.Time) && script.Time is double t)
      s = s with { Time = t };

    ImageSynthesizer? synthesizer = null;
    if (script.Renderer != null)
    {
      string type = script.Renderer.GetType().Name;
      if ((given & GivenSettings.Sampling) != 0)
        notes.Add($"{name(Setting.SamplesPerPixel)}/{name(Setting.Jitter)} given: the script's renderer {type} is not used");
      else if (script.Renderer is ImageSynthesizer synth)
      {
        synth.Width = s.Width;
        synth.Height = s.Height;
        synthesizer = synth;
        if (!given.HasFlag(GivenSettings.Gamma))
          s = s with { Gamma = !Rendering.Execution.RenderDefaults.IsLinearGamma(synth.Gamma) ? synth.Gamma : 1.0 };
      }
      else
        notes.Add($"the script's renderer {type} is not an ImageSynthesizer; using the default renderer");
    }

    IImageFunction? function = null;
    // A given algorithm replaces the script's function, unless that already is its exact class (then it keeps its settings).
    Type? chosen = script.ImageFunction != null && given.HasFlag(GivenSettings.Algorithm) ? s.CreateImageFunction().GetType() : null;
    if (chosen != null && script.ImageFunction!.GetType() != chosen)
      notes.Add($"{name(Setting.Algorithm)} given: the script's image function {script.ImageFunction.GetType().Name} is replaced by {chosen.Name}");
    else if (script.ImageFunction != null)
    {
      if (given.HasFlag(GivenSettings.Accel) && script.ImageFunction is RayCasting rc)
        rc.Accel = s.Accel;
      if (script.ImageFunction is RayTracing rt)
      {
        if (given.HasFlag(GivenSettings.Shadows)) rt.DoShadows = s.Shadows;
        if (given.HasFlag(GivenSettings.Reflections)) rt.DoReflections = s.Reflections;
        if (given.HasFlag(GivenSettings.Refractions)) rt.DoRefractions = s.Refractions;
        function = rt;
      }
      else if (TurnsSomethingOff(s, given))
        notes.Add($"{name(Setting.Shadows)}/{name(Setting.Reflections)}/{name(Setting.Refractions)} given: the script's image function {script.ImageFunction.GetType().Name} is replaced by RayTracing");
      else
        function = script.ImageFunction;
    }

    AddIgnoredSwitches(notes, s, given, function, name);
    return new RenderPlan(s.Validate(), function, synthesizer, notes);
  }

  /// <summary>
  /// A note for each given switch the image function does not follow, so it is not silently swallowed: path tracing
  /// follows every bounce whatever --no-reflections and --no-refractions say (shadows it does follow).
  /// </summary>
  static void AddIgnoredSwitches(List<string> notes, RenderSettings s, GivenSettings given, IImageFunction? function, Func<Setting, string> name)
  {
    // The image function says whether it follows the switches (MonteCarloRayTracing); path tracing does not.
    bool followsSwitches = function != null ? function is not MonteCarloRayTracing { FollowsRayTypeSwitches: false } : s.Algorithm != RenderAlgorithm.Path;
    if (followsSwitches)
      return;
    var ignored = new List<string>();
    if (given.HasFlag(GivenSettings.Reflections) && !s.Reflections)
      ignored.Add(name(Setting.Reflections));
    if (given.HasFlag(GivenSettings.Refractions) && !s.Refractions)
      ignored.Add(name(Setting.Refractions));
    if (ignored.Count > 0)
      notes.Add($"{string.Join("/", ignored)} given: path tracing scatters by the materials at every bounce, so {(ignored.Count == 1 ? "it does" : "they do")} not apply");
  }

  static bool TurnsSomethingOff(RenderSettings s, GivenSettings given) =>
    (given.HasFlag(GivenSettings.Shadows) && !s.Shadows) ||
    (given.HasFlag(GivenSettings.Reflections) && !s.Reflections) ||
    (given.HasFlag(GivenSettings.Refractions) && !s.Refractions);

  static string Words(Setting setting) => setting switch
  {
    Setting.SamplesPerPixel => "samples per pixel",
    Setting.TileSize => "tile size",
    _ => setting.ToString().ToLowerInvariant(),
  };
}
