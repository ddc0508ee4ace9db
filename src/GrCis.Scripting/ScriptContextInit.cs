using System;

namespace GrCis.Scripting;

/// <summary>
/// What the context holds when a script starts, as GrCis's demos filled it before every script call
/// (<c>Scripts.ContextInit</c>, since May 2020): the scene's name, the image size and supersampling of the
/// front end, and the animation range. A script may read any of them without setting it first; a value
/// the script writes is the script's choice (<see cref="ScriptScene"/>), one it leaves alone is not.
/// </summary>
/// <remarks>
/// A front end passes what it would use if the script chose nothing: the value the user gave, else its
/// default. GrCis's own defaults are those of <see cref="Default"/>.
/// </remarks>
public sealed record ScriptContextInit
{
  /// <summary>GrCis's values: 640×480, supersampling 1, animation 0 to 10 s at 25 fps.</summary>
  public static ScriptContextInit Default { get; } = new();

  /// <summary>The scene's name (<c>SceneName</c>); null = the script's file name.</summary>
  public string? SceneName { get; init; }

  /// <summary>Image width in pixels (<c>Width</c>).</summary>
  public int Width { get; init; } = Rendering.Execution.RenderDefaults.Width;

  /// <summary>Image height in pixels (<c>Height</c>).</summary>
  public int Height { get; init; } = Rendering.Execution.RenderDefaults.Height;

  /// <summary>Samples per pixel (<c>SuperSampling</c>).</summary>
  public int SuperSampling { get; init; } = Rendering.Execution.RenderDefaults.SamplesPerPixel;

  /// <summary>Animation start (<c>Start</c>), seconds.</summary>
  public double Start { get; init; } = Rendering.Execution.RenderDefaults.AnimationStart;

  /// <summary>Animation end (<c>End</c>), seconds.</summary>
  public double End { get; init; } = Rendering.Execution.RenderDefaults.AnimationEnd;

  /// <summary>Frames per second (<c>FPS</c>).</summary>
  public double Fps { get; init; } = Rendering.Execution.RenderDefaults.Fps;
}
