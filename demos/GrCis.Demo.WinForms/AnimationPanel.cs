using System;
using System.Drawing;
using System.Globalization;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using System.Windows.Forms;
using GrCis.Hosting;
using GrCis.Interactive;

namespace GrCis.Demo.WinForms;

/// <summary>
/// The animation row: a still at a chosen time, or every frame from/to at a frame rate with ETA,
/// rendered by <see cref="AnimationRun"/> (the engine of <c>grcis animate</c>) into numbered PNGs.
/// </summary>
sealed class AnimationPanel : FlowLayoutPanel
{
  readonly DemoController controller;
  readonly CheckBox still = new() { Text = "Still at time", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly NumericUpDown time = Number(0m);
  readonly NumericUpDown from = Number(0m);
  readonly NumericUpDown to = Number((decimal)AnimationRange.DefaultEnd);
  readonly NumericUpDown fps = new() { Minimum = 0.1m, Maximum = 240m, DecimalPlaces = 1, Value = (decimal)AnimationRange.DefaultFps, Width = 60 };
  readonly ToolTip tips = new();
  // The boxes the user changed since the scene was chosen: their values win; the others are the script's (else the defaults).
  readonly System.Collections.Generic.HashSet<NumericUpDown> given = new();
  bool showing;
  readonly Button animate = new() { Text = "Animate…", AutoSize = true };
  readonly Button stop = new() { Text = "Stop", AutoSize = true, Enabled = false };
  readonly Label status = new() { AutoSize = true, Anchor = AnchorStyles.Left };
  CancellationTokenSource? running;

  public AnimationPanel(DemoController controller)
  {
    this.controller = controller ?? throw new ArgumentNullException(nameof(controller));
    AutoSize = true;
    WrapContents = false;
    Dock = DockStyle.Fill;

    Controls.Add(still);
    Controls.Add(time);
    Controls.Add(Caption("Animation from"));
    Controls.Add(from);
    Controls.Add(Caption("to"));
    Controls.Add(to);
    Controls.Add(Caption("fps"));
    Controls.Add(fps);
    Controls.Add(animate);
    Controls.Add(stop);
    Controls.Add(status);

    still.CheckedChanged += (_, _) => ApplyStillTime();
    time.ValueChanged += (_, _) => ApplyStillTime();
    foreach (NumericUpDown box in new[] { from, to, fps })
      box.ValueChanged += (_, _) =>
      {
        if (showing)
          return;
        given.Add(box);
        Mark(box, false);
      };
    animate.Click += async (_, _) => await AnimateAsync();
    stop.Click += (_, _) => running?.Cancel();
  }

  /// <summary>A frame was rendered (on the UI thread): show it.</summary>
  public event EventHandler<FrameRenderedEventArgs>? FrameShown;

  /// <summary>
  /// A scene was chosen or built: each box shows the script's value (CTX_START_ANIM, CTX_END_ANIM, CTX_FPS), marked as
  /// the script's, else the default (0 to 10 s at 25 fps, what grcis animate takes); a box the user changed keeps theirs.
  /// </summary>
  public void ShowOverrides(SceneOverrides? overrides)
  {
    showing = true;
    Show(from, overrides?.Start, AnimationRange.DefaultStart);
    Show(to, overrides?.End, AnimationRange.DefaultEnd);
    Show(fps, overrides?.Fps, AnimationRange.DefaultFps);
    showing = false;
  }

  void Show(NumericUpDown box, double? script, double fallback)
  {
    if (script is double v)
      given.Remove(box);   // a newly chosen script's value shows until changed again
    else if (given.Contains(box))
      return;
    box.Value = Clamp(box, script ?? fallback);
    Mark(box, script != null);
  }

  void Mark(NumericUpDown box, bool script)
  {
    box.ForeColor = script ? SystemColors.HotTrack : SystemColors.WindowText;
    tips.SetToolTip(box, script ? "The script's value; change it to use your own" : null);
  }

  void ApplyStillTime() =>
    controller.Settings = controller.Settings with { Time = still.Checked ? (double)time.Value : null };

  async Task AnimateAsync()
  {
    if (controller.Selected == null)
      return;
    using var dialog = new SaveFileDialog
    {
      Title = "Frames (#### becomes the frame number)",
      Filter = "PNG frames|*.png",
      FileName = "out####.png",
    };
    if (dialog.ShowDialog(FindForm()) != DialogResult.OK)
      return;

    AnimationRun run;
    try
    {
      // The user's values win; the others are the script's, else the scene's, else the defaults (grcis animate's rule).
      run = controller.CreateAnimation(Given(from), Given(to), Given(fps));
    }
    catch (Exception ex) when (ex is SceneEvaluationException or ArgumentException or InvalidOperationException)
    {
      MessageBox.Show(FindForm(), ex.Message, "Animation", MessageBoxButtons.OK, MessageBoxIcon.Error);
      return;
    }

    using var cts = new CancellationTokenSource();
    running = cts;
    animate.Enabled = false;
    stop.Enabled = true;
    status.Text = $"0 / {run.Timeline.FrameCount}";
    SynchronizationContext? ui = SynchronizationContext.Current;
    run.FrameRendered += (_, e) => ui?.Post(_ => OnFrame(e), null);
    try
    {
      int frames = await run.RunAsync(dialog.FileName, cts.Token);
      status.Text = $"{frames} frame(s) written to {Path.GetDirectoryName(Path.GetFullPath(dialog.FileName))}";
    }
    catch (Exception ex) when (ex is Rendering.Imaging.ImageSaveException or IOException or OperationCanceledException)
    {
      status.Text = ex is OperationCanceledException ? "stopped" : ex.Message;
    }
    finally
    {
      running = null;
      animate.Enabled = true;
      stop.Enabled = false;
    }
  }

  void OnFrame(FrameRenderedEventArgs e)
  {
    status.Text = string.Create(CultureInfo.InvariantCulture,
      $"frame {e.FramesDone} / {e.FramesTotal} (t = {e.Time:0.###}), ETA {e.Eta:hh\\:mm\\:ss}");
    FrameShown?.Invoke(this, e);
  }

  double? Given(NumericUpDown box) => given.Contains(box) ? (double)box.Value : null;

  static NumericUpDown Number(decimal value) =>
    new() { Minimum = -100000m, Maximum = 100000m, DecimalPlaces = 3, Increment = 0.1m, Value = value, Width = 70 };

  static decimal Clamp(NumericUpDown box, double value) =>
    double.IsFinite(value) && Math.Abs(value) < 1e9 ? Math.Clamp((decimal)value, box.Minimum, box.Maximum) : box.Value;

  static Label Caption(string text) =>
    new() { Text = text, AutoSize = true, Anchor = AnchorStyles.Left, TextAlign = ContentAlignment.MiddleLeft };

  protected override void Dispose(bool disposing)
  {
    if (disposing)
      running?.Cancel();
    base.Dispose(disposing);
  }
}
