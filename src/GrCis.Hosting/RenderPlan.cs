using System.Collections.Generic;
using Rendering;
using Rendering.Execution;

namespace GrCis.Hosting;

/// <summary>
/// What <see cref="Precedence.Resolve"/> decided: the effective settings and the script's objects that render.
/// The one builder between front ends and the renderer: the image function, the sampler
/// (<see cref="ImageSynthesizer"/>) and the execution options of every render come from here.
/// </summary>
public sealed class RenderPlan
{
  internal RenderPlan(RenderSettings settings, IImageFunction? function, ImageSynthesizer? synthesizer, IReadOnlyList<string> notes)
  {
    Settings = settings;
    ImageFunction = function;
    Synthesizer = synthesizer;
    Notes = notes;
  }

  /// <summary>Settings after precedence, validated (what the render and its summary use).</summary>
  public RenderSettings Settings { get; }

  /// <summary>The script's image function (given switches applied), or null for <see cref="RenderSettings.CreateImageFunction"/>.</summary>
  public IImageFunction? ImageFunction { get; }

  /// <summary>The script's renderer (sized to the image), or null for <see cref="RenderSettings.CreateSynthesizer"/>.</summary>
  public ImageSynthesizer? Synthesizer { get; }

  /// <summary>Things the user should know: a script object not used, and why.</summary>
  public IReadOnlyList<string> Notes { get; }

  /// <summary>The image function to render with: the script's, else a new one from the settings.</summary>
  public IImageFunction CreateImageFunction(IRayScene? scene = null) => ImageFunction ?? Settings.CreateImageFunction(scene);

  /// <summary>The renderer to render with: the script's, else a new one from the settings.</summary>
  public ImageSynthesizer CreateSynthesizer() => Synthesizer ?? Settings.CreateSynthesizer();

  /// <summary>
  /// The execution options (threads, tiles, seed, sampler) of frame <paramref name="frame"/>; only <paramref name="tiles"/>
  /// when given; on <paramref name="threads"/> threads when given (an animation frame rendered beside others), else the settings'.
  /// </summary>
  public RenderOptions CreateOptions(int frame = 0, IReadOnlyList<Tile>? tiles = null, int? threads = null)
  {
    RenderOptions options = Settings.ToRenderOptions(frame) with { Tiles = tiles };
    return threads is int n ? options with { Threads = n } : options;
  }
}
