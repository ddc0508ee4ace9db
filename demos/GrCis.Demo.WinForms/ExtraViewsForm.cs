using System;
using System.Windows.Forms;
using GrCis.Interactive;
using Rendering.Imaging;

namespace GrCis.Demo.WinForms;

/// <summary>GrCis's "Additional views": one tab per map (depth, normals, ray counts), value read-out, export.</summary>
sealed class ExtraViewsForm : Form
{
  readonly ExtraViews views;
  readonly FloatImage? colors;
  readonly double gamma;
  readonly TabControl tabs = new() { Dock = DockStyle.Fill };
  readonly Label readout = new() { Dock = DockStyle.Fill, AutoSize = false, TextAlign = System.Drawing.ContentAlignment.MiddleLeft };

  public ExtraViewsForm(ExtraViews views, FloatImage? colors, double gamma)
  {
    this.views = views ?? throw new ArgumentNullException(nameof(views));
    this.colors = colors;
    this.gamma = gamma;
    Text = "Extra views";
    ClientSize = new System.Drawing.Size(Math.Clamp(views.Width + 24, 480, 1400), Math.Clamp(views.Height + 110, 360, 1000));
    StartPosition = FormStartPosition.CenterParent;

    foreach (MapKind kind in Enum.GetValues<MapKind>())
    {
      var view = new ImageView { Dock = DockStyle.Fill, Image = BitmapConversion.ToBitmap(Rgb8Image.FromFloatImage(views.ToImage(kind))) };
      MapKind k = kind;
      view.PixelHovered += (_, e) => readout.Text = views.Describe(k, e.X, e.Y);
      view.PixelClicked += (_, e) => readout.Text = views.Describe(k, e.X, e.Y);
      var page = new TabPage(Title(kind)) { Tag = kind };
      page.Controls.Add(view);
      tabs.TabPages.Add(page);
    }
    tabs.SelectedIndexChanged += (_, _) => readout.Text = RangeText(CurrentKind);

    var savePng = new Button { Text = "Save PNG…", AutoSize = true };
    var saveCsv = new Button { Text = "Save CSV…", AutoSize = true };
    var savePly = new Button { Text = "Save point cloud…", AutoSize = true };
    savePng.Click += (_, _) => Export("PNG image|*.png", ".png", path => views.SavePng(CurrentKind, path));
    saveCsv.Click += (_, _) => Export("CSV table|*.csv", ".csv", path => views.SaveCsv(CurrentKind, path));
    savePly.Click += (_, _) => Export("PLY point cloud|*.ply", ".ply", path => views.SavePointCloud(path, this.colors, this.gamma));

    var buttons = new FlowLayoutPanel { Dock = DockStyle.Fill, AutoSize = true, WrapContents = false };
    buttons.Controls.Add(savePng);
    buttons.Controls.Add(saveCsv);
    buttons.Controls.Add(savePly);

    var layout = new TableLayoutPanel { Dock = DockStyle.Fill, ColumnCount = 1, RowCount = 3 };
    layout.RowStyles.Add(new RowStyle(SizeType.Percent, 100f));
    layout.RowStyles.Add(new RowStyle(SizeType.Absolute, 24f));
    layout.RowStyles.Add(new RowStyle(SizeType.AutoSize));
    layout.Controls.Add(tabs, 0, 0);
    layout.Controls.Add(readout, 0, 1);
    layout.Controls.Add(buttons, 0, 2);
    Controls.Add(layout);
    readout.Text = RangeText(CurrentKind);
  }

  MapKind CurrentKind => tabs.SelectedTab?.Tag is MapKind k ? k : MapKind.Depth;

  string RangeText(MapKind kind)
  {
    (double min, double max) = views.Range(kind);
    string text = FormattableString.Invariant($"{Title(kind)}: {min:0.###} to {max:0.###}");
    return kind == MapKind.AllRays && !views.AllRaysKnown ? text + " (primary rays only: not a ray tracer)" : text;
  }

  static string Title(MapKind kind) => kind switch
  {
    MapKind.Depth => "Depth",
    MapKind.NormalRelative => "Normals (to view)",
    MapKind.NormalAbsolute => "Normals (absolute)",
    MapKind.PrimaryRays => "Primary rays",
    MapKind.Noise => "Noise",
    _ => "All rays",
  };

  void Export(string filter, string extension, Action<string> save)
  {
    using var dialog = new SaveFileDialog { Filter = filter, DefaultExt = extension, FileName = CurrentKind + extension };
    if (dialog.ShowDialog(this) != DialogResult.OK)
      return;
    try
    {
      save(dialog.FileName);
    }
    catch (Exception ex) when (ex is ImageSaveException or System.IO.IOException or UnauthorizedAccessException)
    {
      MessageBox.Show(this, ex.Message, "Extra views", MessageBoxButtons.OK, MessageBoxIcon.Error);
    }
  }
}
