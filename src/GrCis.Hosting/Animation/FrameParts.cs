using System;
using System.Collections.Generic;
using Rendering;
using Rendering.Accel;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// The image function, renderer and options of each frame, from the same <see cref="RenderPlan"/> as a still. Frames
/// rendering at once must not share a function or a renderer (a renderer holds its image function, an image function
/// its prepared scene), so each frame gets fresh ones: the plan's from the settings, or copies of the scene script's
/// own (CTX_ALGORITHM, CTX_SYNTHESIZER) when they are the library's classes. A script object of another class (one
/// the script declares) cannot be copied: it is used as it is, on the script's scene, one frame at a time
/// (<see cref="Sequential"/>). Which objects may be copied is decided once, here.
/// </summary>
public sealed class FrameParts
{
  readonly IImageFunction? scriptFunction;
  readonly ImageSynthesizer? scriptSynthesizer;

  public FrameParts(RenderPlan plan)
  {
    ArgumentNullException.ThrowIfNull(plan);
    Plan = plan;
    scriptFunction = plan.ImageFunction;
    scriptSynthesizer = plan.Synthesizer;
    Sequential = (scriptFunction != null && !FrontEndRules.IsCopyableRayCaster(scriptFunction)) ||
                 (scriptSynthesizer != null && !FrontEndRules.IsLibraryClass(scriptSynthesizer));
  }

  /// <summary>What precedence decided: the builder of every frame's function, renderer and options.</summary>
  public RenderPlan Plan { get; }

  /// <summary>True when the script's own objects must render every frame, one after another, on its scene.</summary>
  public bool Sequential { get; }

  /// <summary>A fresh image function for one frame; <paramref name="scene"/> null = render the worker's scene (<see cref="MT.scene"/>).</summary>
  public IImageFunction CreateFunction(IRayScene? scene)
  {
    if (scriptFunction == null || Sequential)
      return Plan.CreateImageFunction(scene);

    // Copyable (decided in the constructor): exactly the library's RayTracing or RayCasting.
    var source = (RayCasting)scriptFunction;
    RayCasting copy = source is RayTracing ? new RayTracing(scene) : new RayCasting(scene);
    copy.CopySettingsFrom(source);   // --accel, when given, was applied to the script's function (Precedence)
    return copy;
  }

  /// <summary>A fresh renderer for one frame (a shallow copy of the script's, or one from the settings).</summary>
  public ImageSynthesizer CreateSynthesizer()
  {
    if (scriptSynthesizer == null || Sequential)
      return Plan.CreateSynthesizer();
    return (ImageSynthesizer)ShallowCopy(scriptSynthesizer);
  }

  /// <summary>The execution options of frame <paramref name="frame"/> on <paramref name="threads"/> threads (the plan's, as a still's).</summary>
  public RenderOptions CreateOptions(int frame, int threads) => Plan.CreateOptions(frame, threads: threads);

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
