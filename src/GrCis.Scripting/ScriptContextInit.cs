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

  public int Width { get; init; } = 640;

  public int Height { get; init; } = 480;

  public int SuperSampling { get; init; } = 1;

  /// <summary>Animation start (<c>Start</c>), seconds.</summary>
  public double Start { get; init; }

  /// <summary>Animation end (<c>End</c>), seconds.</summary>
  public double End { get; init; } = 10.0;

  public double Fps { get; init; } = 25.0;
}
