using System;
using System.Collections.Generic;
using Rendering;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// The image function and renderer of each frame. Frames rendering at once must not share them
/// (a renderer holds its image function, an image function its prepared scene), so each frame gets
/// fresh ones: from the render settings, or copies of the scene script's own (CTX_ALGORITHM,
/// CTX_SYNTHESIZER) when they are the library's classes. A script object of another class (one
/// the script declares) cannot be copied: it is used as it is, on the script's scene, one frame
/// at a time (<see cref="Sequential"/>).
/// </summary>
public sealed class FrameParts
{
  readonly RenderSettings settings;
  readonly IImageFunction? scriptFunction;
  readonly ImageSynthesizer? scriptSynthesizer;

  public FrameParts(RenderSettings settings, IImageFunction? scriptFunction = null, ImageSynthesizer? scriptSynthesizer = null)
  {
    this.settings = settings;
    this.scriptFunction = scriptFunction;
    this.scriptSynthesizer = scriptSynthesizer;
    Sequential = (scriptFunction != null && !IsLibraryRayCaster(scriptFunction)) ||
                 (scriptSynthesizer != null && scriptSynthesizer.GetType().Assembly != typeof(ImageSynthesizer).Assembly);
  }

  /// <summary>True when the script's own objects must render every frame, one after another, on its scene.</summary>
  public bool Sequential { get; }

  /// <summary>A fresh image function for one frame; <paramref name="scene"/> null = render the worker's scene (<see cref="MT.scene"/>).</summary>
  public IImageFunction CreateFunction(IRayScene? scene)
  {
    if (scriptFunction == null)
    {
      return settings.CreateImageFunction(scene);
    }
    if (Sequential || !IsLibraryRayCaster(scriptFunction))
      return scriptFunction;

    var source = (RayCasting)scriptFunction;
    RayCasting copy = source is RayTracing ? new RayTracing(scene) : new RayCasting(scene);
    copy.CopySettingsFrom(source);   // --accel, when given, was applied to the script's function (Precedence)
    return copy;
  }

  /// <summary>A fresh renderer for one frame (a shallow copy of the script's, or one from the settings).</summary>
  public ImageSynthesizer CreateSynthesizer()
  {
    if (scriptSynthesizer == null)
      return settings.CreateSynthesizer();
    if (Sequential)
      return scriptSynthesizer;
    return (ImageSynthesizer)ShallowCopy(scriptSynthesizer);
  }

  /// <summary>Exactly the library's RayCasting or RayTracing (whose settings we know how to copy).</summary>
  static bool IsLibraryRayCaster(IImageFunction f) => f.GetType() == typeof(RayTracing) || f.GetType() == typeof(RayCasting);

  static object ShallowCopy(object o) =>
    typeof(object).GetMethod(nameof(MemberwiseClone), System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.NonPublic)!
      .Invoke(o, null)!;

  /// <summary>Words for the user about what was chosen (empty when nothing is worth saying).</summary>
  public IEnumerable<string> Notes()
  {
    if (Sequential)
      yield return "the script's own image function or renderer is a class of its own: frames render one at a time";
  }
}
