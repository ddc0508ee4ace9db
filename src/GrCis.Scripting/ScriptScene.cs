using System.Collections.Generic;
using Rendering;

namespace GrCis.Scripting;

/// <summary>
/// What a script run produced: the filled scene and the settings the script put in the context.
/// A null setting means the script left it alone; the caller applies its own precedence
/// (command line, then script, then default).
/// </summary>
public sealed class ScriptScene
{
  internal ScriptScene(CompiledScript script, IRayScene scene, Dictionary<string, object> context, bool preprocessed)
  {
    Script = script;
    Scene = scene;
    Context = context;
    Preprocessed = preprocessed;
  }

  public CompiledScript Script { get; }

  /// <summary>The scene the regular (non-preprocessing) call filled.</summary>
  public IRayScene Scene { get; }

  /// <summary>The context after the run (reuse it for further calls of the same batch, one per thread).</summary>
  public Dictionary<string, object> Context { get; }

  /// <summary>True when this run included the preprocessing call.</summary>
  public bool Preprocessed { get; }

  public int? Width { get; internal set; }

  public int? Height { get; internal set; }

  public int? SuperSampling { get; internal set; }

  /// <summary>Image function from <see cref="PropertyName.CTX_ALGORITHM"/>.</summary>
  public IImageFunction? Algorithm { get; internal set; }

  /// <summary>Renderer from <see cref="PropertyName.CTX_SYNTHESIZER"/>.</summary>
  public IRenderer? Synthesizer { get; internal set; }

  /// <summary>Parameter help text from <see cref="PropertyName.CTX_TOOLTIP"/>.</summary>
  public string? ToolTip { get; internal set; }

  public double? Start { get; internal set; }

  public double? End { get; internal set; }

  public double? Fps { get; internal set; }

  public double? Time { get; internal set; }
}
