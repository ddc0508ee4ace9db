using Rendering;

namespace GrCis.Hosting;

/// <summary>What a scene script chose through its context (GrCis's CTX_* keys); null = not set by the script.</summary>
public sealed record ScriptChoices
{
  /// <summary>The script's name for messages (its file name).</summary>
  public string Name { get; init; } = "the script";

  /// <summary>CTX_WIDTH, CTX_HEIGHT.</summary>
  public int? Width { get; init; }

  public int? Height { get; init; }

  /// <summary>CTX_SUPERSAMPLING.</summary>
  public int? SamplesPerPixel { get; init; }

  /// <summary>CTX_ALGORITHM.</summary>
  public IImageFunction? ImageFunction { get; init; }

  /// <summary>CTX_SYNTHESIZER.</summary>
  public IRenderer? Renderer { get; init; }

  /// <summary>CTX_TIME: the time the script set for a still.</summary>
  public double? Time { get; init; }
}
