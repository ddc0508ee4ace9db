using System;
using System.Drawing;
using System.Globalization;
using System.Threading;
using System.Threading.Tasks;
using System.Windows.Forms;
using GrCis.Interactive;
using GrCis.Hosting;

namespace GrCis.Demo.WinForms;

/// <summary>The settings fields: the script's own values shown and marked, the user's changes given.</summary>
sealed partial class MainForm
{
  void ShowSceneInfo(SceneEntry? entry)
  {
    param.Text = entry?.ParameterText ?? "";
    param.Enabled = entry != null;
    tips.SetToolTip(param, entry?.Tooltip ?? "Parameters of the scene (key=value, comma separated)");
    overrides.Text = entry?.Overrides is { IsEmpty: false } o ? "script sets " + o : "";
    animation.ShowOverrides(entry?.Overrides);
    ShowSettings();
  }

  /// <summary>A scene was chosen: build it (not render) to show the script's own values in the fields.</summary>
  async Task ReadScriptValuesAsync()
  {
    SceneEntry? entry = controller.Selected;
    if (entry == null)
      return;
    SceneOverrides values;
    try
    {
      values = await controller.ReadScriptValuesAsync(entry);
    }
    catch (Exception ex) when (ex is SceneEvaluationException or OperationCanceledException)
    {
      overrides.Text = ex is OperationCanceledException ? "" : "script error (Render shows it)";
      return;
    }
    if (controller.Selected != entry)
      return;
    // The script's values show in their fields again, until the user changes them.
    GivenSettings scriptSets = (values.Width != null || values.Height != null ? GivenSettings.Size : 0) |
                               (values.Supersampling != null ? GivenSettings.SamplesPerPixel : 0);
    controller.Given &= ~scriptSets;
    ShowSceneInfo(entry);
  }

  void ShowSettings()
  {
    showing = true;
    RenderSettings s = controller.ShownSettings();
    resolution.Text = $"Resolution {s.Width} x {s.Height}";
    Mark(resolution, controller.IsScriptValue(Setting.Size));
    supersampling.Value = Math.Clamp(s.SamplesPerPixel, (int)supersampling.Minimum, (int)supersampling.Maximum);
    Mark(supersampling, controller.IsScriptValue(Setting.SamplesPerPixel));
    algorithm.Items[0] = $"scene's choice ({controller.Selected?.Overrides?.Algorithm ?? "ray tracing"})";
    jitter.Checked = s.Jitter > 0.0;
    shadows.Checked = s.Shadows;
    reflections.Checked = s.Reflections;
    refractions.Checked = s.Refractions;
    multithreading.Checked = s.Threads != 1;
    algorithm.SelectedIndex = Math.Max(Array.IndexOf(Algorithms, controller.Algorithm), 0);
    preview.SelectedIndex = Math.Max(Array.IndexOf(Previews, controller.Progressive), 0);
    showing = false;
  }

  /// <summary>Marks a field that shows the script's own value (blue, with a tooltip).</summary>
  void Mark(Control field, bool script)
  {
    field.ForeColor = script ? SystemColors.HotTrack : SystemColors.ControlText;
    tips.SetToolTip(field, script ? "The script's value; change it to use your own" : null);
  }

  // Set while the fields are filled from the settings: those changes are not the user's.
  bool showing;

  void Apply(Func<RenderSettings, RenderSettings> change, GivenSettings given = GivenSettings.None)
  {
    if (showing)
      return;
    // The field shows the script's value until changed: the rest of the settings keep the user's own.
    controller.Settings = change(controller.Settings);
    controller.Given |= given;
    if (given != GivenSettings.None)
      ShowSettings();
  }

  void ChooseResolution()
  {
    using var dialog = new ResolutionForm(controller.ShownSettings().Width, controller.ShownSettings().Height);
    if (dialog.ShowDialog(this) != DialogResult.OK)
      return;
    Apply(s => s with { Width = dialog.ImageWidth, Height = dialog.ImageHeight }, GivenSettings.Size);
  }
}
