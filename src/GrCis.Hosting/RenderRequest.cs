namespace GrCis.Hosting;

/// <summary>
/// What a front end asks to render: a scene source (a built-in scene or a script, with its parameter text
/// and modules), the requested settings, which of them the user gave explicitly, and the time of a still.
/// <see cref="Prepare"/> builds the scene and applies the one precedence rule.
/// </summary>
/// <param name="Time">The time a moving scene is rendered at; null = the script's choice, else the scene's start.</param>
public sealed record RenderRequest(ISceneSource Source, RenderSettings Settings, GivenSettings Given = GivenSettings.None, double? Time = null)
{
  /// <summary>The animation start the user gave (a script finds it in its context); null = GrCis's 0.</summary>
  public double? Start { get; init; }

  /// <summary>The animation end the user gave; null = GrCis's 10 s.</summary>
  public double? End { get; init; }

  /// <summary>The frame rate the user gave; null = GrCis's 25.</summary>
  public double? Fps { get; init; }

  /// <summary>What a script finds in its context when it starts: the requested size and supersampling, the given animation range.</summary>
  public GrCis.Scripting.ScriptContextInit ScriptContext => new()
  {
    Width = Settings.Width,
    Height = Settings.Height,
    SuperSampling = Settings.SamplesPerPixel,
    Start = Start ?? GrCis.Scripting.ScriptContextInit.Default.Start,
    End = End ?? GrCis.Scripting.ScriptContextInit.Default.End,
    Fps = Fps ?? GrCis.Scripting.ScriptContextInit.Default.Fps,
  };

  /// <summary>Builds the scene and resolves the settings against the script's choices.</summary>
  /// <param name="name">How the front end names a setting in notes (an option such as <c>--spp</c>); null = plain words.</param>
  /// <exception cref="ScriptChoiceException">The script asks for an image size or sample count out of range.</exception>
  /// <exception cref="InvalidSettingException">A requested setting out of range.</exception>
  /// <exception cref="GrCis.Scripting.ScriptCompilationException">The script or a module did not compile.</exception>
  /// <exception cref="GrCis.Scripting.ScriptRuntimeException">The script threw.</exception>
  public PreparedRender Prepare(System.Func<Setting, string>? name = null) => PreparedRender.Create(this, name);
}
