using System;
using System.Threading;
using System.Threading.Tasks;
using Rendering.Execution;
using GrCis.Hosting;

namespace GrCis.Interactive;

/// <summary>Honest settings: what the script itself sets, and what the fields show by the one precedence rule.</summary>
public sealed partial class DemoController
{
  /// <summary>
  /// Builds <paramref name="entry"/> (the selected scene by default) without rendering it, on a worker thread, to learn
  /// the script's own values (size, supersampling, algorithm, animation range) and its tooltip, so the fields can show
  /// them as soon as a scene is chosen. <see cref="Stop"/> or <paramref name="cancel"/> ends a script stuck in a loop.
  /// </summary>
  /// <returns>The values the script sets (<see cref="SceneEntry.Overrides"/>); empty for a built-in scene.</returns>
  /// <exception cref="SceneEvaluationException">The scene could not be built; the message is for the user.</exception>
  public async Task<SceneOverrides> ReadScriptValuesAsync(SceneEntry? entry = null, CancellationToken cancel = default)
  {
    entry ??= Selected ?? throw new InvalidOperationException("Choose a scene first.");
    CancellationTokenSource reading;
    lock (sync)
    {
      inspecting?.Cancel();   // the scene chosen before this one
      reading = inspecting = CancellationTokenSource.CreateLinkedTokenSource(cancel);
    }
    try
    {
      // The fields' values do not reach the script; only what it sets itself is read back.
      BuiltScene built = await Task.Factory.StartNew(() =>
      {
        using Interruption.Scope interruption = Interruption.Use(reading.Token);
        return Catalog.Build(entry, entry.ParameterText, new RenderSettings(), GivenSettings.None);
      }, reading.Token, TaskCreationOptions.LongRunning, TaskScheduler.Default).ConfigureAwait(false);
      return built.Overrides;
    }
    finally
    {
      lock (sync)
      {
        if (inspecting == reading)
          inspecting = null;
        reading.Dispose();
      }
    }
  }

  /// <summary>
  /// What the settings fields show for the selected scene, by the one precedence rule (<see cref="Precedence"/>): a
  /// setting the user gave (<see cref="Given"/>) as set, else the script's own value (<see cref="SceneEntry.Overrides"/>,
  /// known once the scene was built), else the field's. <see cref="IsScriptValue"/> tells which are the script's.
  /// </summary>
  public RenderSettings ShownSettings()
  {
    SceneOverrides? script = Selected?.Overrides;
    if (script == null)
      return Settings;
    var choices = new ScriptChoices { Width = script.Width, Height = script.Height, SamplesPerPixel = script.Supersampling };
    try
    {
      return Precedence.Resolve(Settings, Given, choices).Settings;
    }
    catch (Exception e) when (e is ScriptChoiceException or InvalidSettingException)
    {
      return Settings;   // the render reports it
    }
  }

  /// <summary>True when the field of <paramref name="setting"/> shows the script's own value: the script sets it and the user did not.</summary>
  public bool IsScriptValue(Setting setting)
  {
    SceneOverrides? script = Selected?.Overrides;
    return setting switch
    {
      Setting.Size => !Given.HasFlag(GivenSettings.Size) && (script?.Width != null || script?.Height != null),
      Setting.SamplesPerPixel => !Given.HasFlag(GivenSettings.SamplesPerPixel) && script?.Supersampling != null,
      Setting.Algorithm => Algorithm == null && script?.Algorithm != null,
      _ => false,
    };
  }
}
