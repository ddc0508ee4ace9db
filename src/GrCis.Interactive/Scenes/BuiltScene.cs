using GrCis.Hosting;
using Rendering;

namespace GrCis.Interactive;

/// <summary>A scene ready to render: the scene itself plus whatever its script chose through the context.</summary>
public sealed class BuiltScene
{
  public BuiltScene(SceneEntry entry, string param, IRayScene scene)
  {
    Entry = entry;
    Param = param;
    Scene = scene;
  }

  public SceneEntry Entry { get; }

  public string Param { get; }

  public IRayScene Scene { get; }

  public SceneOverrides Overrides { get; init; } = new();

  /// <summary>Image function the script chose (CTX_ALGORITHM), else null = ray tracing from the settings.</summary>
  public IImageFunction? ImageFunction { get; init; }

  /// <summary>Renderer the script chose (CTX_SYNTHESIZER), else null = from the settings.</summary>
  public IRenderer? Renderer { get; init; }

  public string? Tooltip { get; init; }

  /// <summary>A render job for this scene: the script's overrides and its chosen function/renderer, by the precedence rule.</summary>
  /// <param name="given">The settings that win over the script's choices (<see cref="RenderJob.Create"/>).</param>
  /// <exception cref="SceneEvaluationException">The script asks for an image size or supersampling out of range.</exception>
  public RenderJob ToJob(RenderSettings settings, GivenSettings given = RenderJob.Given)
  {
    var choices = new ScriptChoices
    {
      Name = Entry.Name,
      Width = Overrides.Width,
      Height = Overrides.Height,
      SamplesPerPixel = Overrides.Supersampling,
    };
    try
    {
      return RenderJob.Create(Scene, settings, ImageFunction, Renderer, Entry.Name, Param, choices, given);
    }
    catch (ScriptChoiceException e)
    {
      throw new SceneEvaluationException(e.Message);
    }
  }
}
