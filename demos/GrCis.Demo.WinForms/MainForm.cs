using System;
using System.Drawing;
using System.Globalization;
using System.Threading;
using System.Threading.Tasks;
using System.Windows.Forms;
using GrCis.Interactive;
using GrCis.Hosting;

namespace GrCis.Demo.WinForms;

/// <summary>
/// GrCis's demo window bound to a <see cref="DemoController"/>: the image on top, then the scene and
/// its parameters, the render settings, the animation row, progress and statistics, and the buttons.
/// Only binding here; what happens lives in GrCis.Interactive.
/// </summary>
sealed partial class MainForm : Form
{
  readonly DemoController controller;
  readonly ImageView view = new() { Dock = DockStyle.Fill };
  readonly ToolTip tips = new() { AutoPopDelay = 20000, InitialDelay = 300 };

  readonly ComboBox scenes = new() { DropDownStyle = ComboBoxStyle.DropDownList, Width = 220 };
  readonly Button addScript = new() { Text = "Script…", AutoSize = true };
  readonly TextBox param = new() { Width = 320 };
  readonly CheckBox watch = new() { Text = "Re-render on save", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly Label overrides = new() { AutoSize = true, Anchor = AnchorStyles.Left, ForeColor = SystemColors.GrayText };

  readonly Button resolution = new() { AutoSize = true };
  readonly NumericUpDown supersampling = new() { Minimum = 1, Maximum = 1024, Value = 1, Width = 56 };
  readonly CheckBox jitter = new() { Text = "Jitter", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly CheckBox shadows = new() { Text = "Shadows", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly CheckBox reflections = new() { Text = "Reflections", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly CheckBox refractions = new() { Text = "Refractions", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly CheckBox multithreading = new() { Text = "Multi-threading", AutoSize = true, Anchor = AnchorStyles.Left };
  readonly ComboBox algorithm = new() { DropDownStyle = ComboBoxStyle.DropDownList, Width = 120 };

  // The algorithm box's items, in order: null = the scene's choice (DemoController.Algorithm).
  static readonly RenderAlgorithm?[] Algorithms = { null, RenderAlgorithm.RayTracing, RenderAlgorithm.Distributed, RenderAlgorithm.Path };

  readonly ComboBox preview = new() { DropDownStyle = ComboBoxStyle.DropDownList, Width = 110 };

  // The preview box's items, in order: null = automatic (DemoController.Progressive).
  static readonly bool?[] Previews = { null, false, true };

  readonly AnimationPanel animation;

  readonly ProgressBar progress = new() { Minimum = 0, Maximum = 1000, Width = 160, Anchor = AnchorStyles.Left };
  readonly Label elapsed = new() { AutoSize = true, Anchor = AnchorStyles.Left, Text = "00:00.0" };
  readonly Label statistics = new() { AutoSize = true, Anchor = AnchorStyles.Left };

  readonly Button render = new() { Text = "Render", AutoSize = true, Font = new Font(Control.DefaultFont, FontStyle.Bold) };
  readonly Button stop = new() { Text = "Stop", AutoSize = true, Enabled = false };
  readonly Button back = new() { Text = "<<", AutoSize = true, Enabled = false };
  readonly Button forward = new() { Text = ">>", AutoSize = true, Enabled = false };
  readonly Button save = new() { Text = "Save image", AutoSize = true, Enabled = false };
  readonly Button extra = new() { Text = "Extra views", AutoSize = true, Enabled = false };
  readonly Button rays = new() { Text = "Pixel rays", AutoSize = true };
  readonly Label pixel = new() { AutoSize = true, Anchor = AnchorStyles.Left };

  readonly System.Windows.Forms.Timer clock = new() { Interval = 100 };
  readonly System.Diagnostics.Stopwatch renderTime = new();
  ProbeForm? probeWindow;
  bool updating;

  public MainForm(DemoController controller)
  {
    this.controller = controller ?? throw new ArgumentNullException(nameof(controller));
    animation = new AnimationPanel(controller);
    Text = "GrCis ray tracing demo";
    ClientSize = new Size(1000, 760);
    StartPosition = FormStartPosition.CenterScreen;
    KeyPreview = true;

    BuildLayout();
    Bind();
    ShowSettings();
    FillScenes();
  }

  void BuildLayout()
  {
    var sceneRow = Row(Caption("Scene"), scenes, addScript, Caption("Parameters"), param, watch, overrides);
    var settingsRow = Row(resolution, Caption("Supersampling"), supersampling, jitter, shadows, reflections, refractions, multithreading,
      Caption("Algorithm"), algorithm, Caption("Preview"), preview);
    var statusRow = Row(progress, elapsed, statistics);
    var buttonRow = Row(render, stop, back, forward, save, extra, rays, pixel);

    var layout = new TableLayoutPanel { Dock = DockStyle.Fill, ColumnCount = 1, RowCount = 6, Margin = new Padding(0) };
    layout.RowStyles.Add(new RowStyle(SizeType.Percent, 100f));
    for (int i = 0; i < 5; i++)
      layout.RowStyles.Add(new RowStyle(SizeType.AutoSize));
    layout.Controls.Add(view, 0, 0);
    layout.Controls.Add(sceneRow, 0, 1);
    layout.Controls.Add(settingsRow, 0, 2);
    layout.Controls.Add(animation, 0, 3);
    layout.Controls.Add(statusRow, 0, 4);
    layout.Controls.Add(buttonRow, 0, 5);
    Controls.Add(layout);
    AcceptButton = render;

    tips.SetToolTip(view, "Wheel: zoom, right-drag: pan, +/-: zoom, R: reset, click: pixel read-out");
    tips.SetToolTip(addScript, "Add a scene script (.cs) to the list");
    tips.SetToolTip(watch, "Render again whenever the selected script changes on disk");
    tips.SetToolTip(supersampling, "Samples per pixel (rounded up to a square grid)");
    algorithm.Items.AddRange(new object[] { "scene's choice", "ray tracing", "distributed", "path tracing" });
    tips.SetToolTip(algorithm, "Image function: the scene's (its script's choice, else ray tracing), or one that replaces the script's, as grcis render --algorithm");
    preview.Items.AddRange(new object[] { "automatic", "tiles", "sample passes" });
    tips.SetToolTip(preview, "Tile by tile, or passes adding samples to every pixel with a noise estimate (automatic: passes for distributed and path tracing); the final image is the same");
  }

  void Bind()
  {
    controller.Catalog.Changed += (_, _) => FillScenes();
    controller.SceneEvaluated += (_, built) => ShowSceneInfo(built.Entry);
    controller.PreviewReady += (_, e) =>
    {
      view.Image = BitmapConversion.ToBitmap(e.ToRgb8());
      if (e.Samples is int spp)
        statistics.Text = $"{spp} spp so far" + (e.Noise is double n ? $", noise {n:0.####} RMSE" : "");
    };
    controller.ProgressChanged += (_, e) => progress.Value = (int)Math.Round(e.Fraction * progress.Maximum);
    controller.RenderCompleted += (_, e) => Finished(e.Result);
    controller.Error += (_, e) =>
    {
      // A script that failed to build (a save watched with "Re-render on save" too) leaves nothing running.
      if (!controller.IsBusy)
        Stopped();
      MessageBox.Show(this, e.Message, Text, MessageBoxButtons.OK, MessageBoxIcon.Warning);
    };
    controller.History.Changed += (_, _) => ShowHistoryButtons();
    controller.ScriptChanged += (_, _) => Started();

    scenes.SelectedIndexChanged += (_, _) =>
    {
      if (updating)
        return;
      controller.Selected = scenes.SelectedItem as SceneEntry;
      ShowSceneInfo(controller.Selected);
      _ = ReadScriptValuesAsync();
    };
    param.TextChanged += (_, _) =>
    {
      if (controller.Selected != null)
        controller.Selected.ParameterText = param.Text;
    };
    watch.CheckedChanged += (_, _) => controller.WatchScript = watch.Checked;
    addScript.Click += (_, _) => AddScript();

    resolution.Click += (_, _) => ChooseResolution();
    // A field the user changes is given: it wins over the script's own value (as a command-line option does).
    supersampling.ValueChanged += (_, _) => Apply(s => s with { SamplesPerPixel = (int)supersampling.Value }, GivenSettings.SamplesPerPixel);
    jitter.CheckedChanged += (_, _) => Apply(s => s with { Jitter = jitter.Checked ? 1.0 : 0.0 }, GivenSettings.Jitter);
    shadows.CheckedChanged += (_, _) => Apply(s => s with { Shadows = shadows.Checked }, GivenSettings.Shadows);
    reflections.CheckedChanged += (_, _) => Apply(s => s with { Reflections = reflections.Checked }, GivenSettings.Reflections);
    refractions.CheckedChanged += (_, _) => Apply(s => s with { Refractions = refractions.Checked }, GivenSettings.Refractions);
    multithreading.CheckedChanged += (_, _) => Apply(s => s with { Threads = multithreading.Checked ? 0 : 1 });
    algorithm.SelectedIndexChanged += (_, _) => controller.Algorithm = Algorithms[Math.Max(algorithm.SelectedIndex, 0)];
    preview.SelectedIndexChanged += (_, _) => controller.Progressive = Previews[Math.Max(preview.SelectedIndex, 0)];

    render.Click += async (_, _) => await RenderAsync();
    stop.Click += (_, _) => controller.Stop();
    back.Click += (_, _) => ShowRecord(controller.History.Back());
    forward.Click += (_, _) => ShowRecord(controller.History.Forward());
    save.Click += (_, _) => SaveImage();
    extra.Click += async (_, _) => await ShowExtraViewsAsync();
    rays.Click += (_, _) => ProbeWindow().Show(this);
    view.PixelClicked += (_, e) => Probe(e.X, e.Y);
    animation.FrameShown += (_, e) => view.Image = BitmapConversion.ToBitmap(Rendering.Execution.RenderSetup.ToDisplayImage(e.Image, controller.Settings.Gamma));

    clock.Tick += (_, _) => elapsed.Text = FormatElapsed(renderTime.Elapsed);
  }

  protected override void OnLoad(EventArgs e)
  {
    // Events of the controller arrive on the UI thread from here on.
    controller.EventContext = SynchronizationContext.Current;
    base.OnLoad(e);
    _ = ReadScriptValuesAsync();
  }

  protected override async void OnShown(EventArgs e)
  {
    base.OnShown(e);
    if (controller.RenderTo is not string target)
      return;
    // -render-to: exactly what Render then Save image do, then close.
    await RenderAsync();
    controller.SaveImage(target);
    Close();
  }

  void FillScenes()
  {
    updating = true;
    scenes.BeginUpdate();
    scenes.Items.Clear();
    foreach (SceneEntry entry in controller.Catalog.Entries)
      scenes.Items.Add(entry);
    scenes.SelectedItem = controller.Selected;
    scenes.EndUpdate();
    updating = false;
    ShowSceneInfo(controller.Selected);
  }

  void AddScript()
  {
    using var dialog = new OpenFileDialog { Filter = "Scene scripts (*.cs)|*.cs|All files|*.*", Title = "Add a scene script" };
    if (dialog.ShowDialog(this) != DialogResult.OK)
      return;
    try
    {
      controller.Selected = controller.Catalog.AddScriptFile(dialog.FileName);
      FillScenes();
    }
    catch (SceneEvaluationException ex)
    {
      MessageBox.Show(this, ex.Message, Text, MessageBoxButtons.OK, MessageBoxIcon.Warning);
    }
  }

  async Task RenderAsync()
  {
    if (controller.Selected == null)
      return;
    Started();
    try
    {
      await controller.RenderAsync();
    }
    catch (ArgumentException ex)
    {
      // A setting out of range (RenderSettings.Validate): a message, not a crash.
      MessageBox.Show(this, ex.Message, Text, MessageBoxButtons.OK, MessageBoxIcon.Warning);
      Stopped();
    }
    // Completion is shown by RenderCompleted; a scene that failed to build raised Error.
    if (!controller.IsRendering && controller.LastResult?.Job != controller.LastJob)
      Stopped();
  }

  void Started()
  {
    render.Enabled = false;
    stop.Enabled = true;
    progress.Value = 0;
    statistics.Text = "rendering…";
    renderTime.Restart();
    clock.Start();
  }

  void Stopped()
  {
    clock.Stop();
    renderTime.Stop();
    render.Enabled = true;
    stop.Enabled = false;
  }

  void Finished(RenderResult result)
  {
    Stopped();
    elapsed.Text = FormatElapsed(result.Statistics.Elapsed);
    progress.Value = result.Succeeded ? progress.Maximum : progress.Value;
    statistics.Text = (result.Cancelled ? "stopped: " : "") + result.Statistics;
    save.Enabled = true;
    extra.Enabled = true;
  }

  void ShowHistoryButtons()
  {
    back.Enabled = controller.History.CanGoBack;
    forward.Enabled = controller.History.CanGoForward;
  }

  void ShowRecord(RenderRecord? record)
  {
    if (record == null)
      return;
    view.Image = BitmapConversion.ToBitmap(record.ToRgb8());
    statistics.Text = record.ToString();
    ShowHistoryButtons();
  }

  void SaveImage()
  {
    using var dialog = new SaveFileDialog { Filter = "PNG image|*.png", DefaultExt = ".png", FileName = (controller.History.Current?.SceneName ?? "render") + ".png" };
    if (dialog.ShowDialog(this) == DialogResult.OK)
      controller.SaveImage(dialog.FileName); // a failure arrives through Error
  }

  async Task ShowExtraViewsAsync()
  {
    // A render that has ended, or was stopped, may still be finishing: its views wait for it (a busy one is not asked).
    if (!await controller.SettleAsync())
      return;
    extra.Enabled = false;
    Cursor = Cursors.WaitCursor;
    try
    {
      RenderResult? last = controller.LastResult;
      ExtraViews views = await Task.Run(() => controller.ComputeExtraViews());
      var form = new ExtraViewsForm(views, last?.Image, last?.Gamma ?? 1.0);
      form.FormClosed += (_, _) => form.Dispose();
      form.Show(this);
    }
    catch (InvalidOperationException ex)
    {
      MessageBox.Show(this, ex.Message, Text, MessageBoxButtons.OK, MessageBoxIcon.Information);
    }
    finally
    {
      Cursor = Cursors.Default;
      extra.Enabled = true;
    }
  }

  void Probe(int x, int y)
  {
    if (controller.LastJob == null || x >= controller.LastJob.Width || y >= controller.LastJob.Height)
      return;
    ProbeResult probe = controller.Probe(x, y);
    double[] c = probe.PixelColor;
    pixel.Text = string.Create(CultureInfo.InvariantCulture, $"[{x},{y}] = ({c[0]:0.###}, {c[1]:0.###}, {c[2]:0.###}), hash {probe.Hash:X}");
    if (probeWindow is { Visible: true })
      probeWindow.Show(probe);
  }

  ProbeForm ProbeWindow()
  {
    if (probeWindow == null || probeWindow.IsDisposed)
    {
      // Beside the main window, but on the screen.
      Rectangle screen = Screen.FromControl(this).WorkingArea;
      probeWindow = new ProbeForm();
      probeWindow.Location = new Point(Math.Max(screen.Left, Math.Min(Right, screen.Right - probeWindow.Width)), Top);
      probeWindow.FormClosing += (_, e) =>
      {
        // Keep the window for the next click; closing just hides it.
        if (e.CloseReason == CloseReason.UserClosing)
        {
          e.Cancel = true;
          probeWindow.Hide();
        }
      };
    }
    return probeWindow;
  }

  protected override void OnFormClosing(FormClosingEventArgs e)
  {
    controller.Stop();
    clock.Stop();
    base.OnFormClosing(e);
  }

  protected override void Dispose(bool disposing)
  {
    if (disposing)
    {
      clock.Dispose();
      tips.Dispose();
      probeWindow?.Dispose();
    }
    base.Dispose(disposing);
  }

  static string FormatElapsed(TimeSpan t) => t.ToString(@"mm\:ss\.f", CultureInfo.InvariantCulture);

  static Label Caption(string text) =>
    new() { Text = text, AutoSize = true, Anchor = AnchorStyles.Left, TextAlign = ContentAlignment.MiddleLeft };

  static FlowLayoutPanel Row(params Control[] controls)
  {
    var row = new FlowLayoutPanel { Dock = DockStyle.Fill, AutoSize = true, WrapContents = true, Margin = new Padding(2) };
    row.Controls.AddRange(controls);
    return row;
  }
}
