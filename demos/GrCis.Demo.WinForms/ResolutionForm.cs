using System;
using System.Drawing;
using System.Windows.Forms;

namespace GrCis.Demo.WinForms;

/// <summary>The "Resolution" dialog: width and height, with the usual presets.</summary>
sealed class ResolutionForm : Form
{
  static readonly Size[] Presets =
  {
    new(320, 240), new(640, 480), new(800, 600), new(1024, 768), new(1280, 720), new(1920, 1080),
  };

  readonly NumericUpDown width = new() { Minimum = 1, Maximum = 16384, Width = 80 };
  readonly NumericUpDown height = new() { Minimum = 1, Maximum = 16384, Width = 80 };
  readonly ComboBox presets = new() { DropDownStyle = ComboBoxStyle.DropDownList, Width = 120 };

  public ResolutionForm(int w, int h)
  {
    Text = "Resolution";
    FormBorderStyle = FormBorderStyle.FixedDialog;
    MaximizeBox = MinimizeBox = false;
    ShowInTaskbar = false;
    StartPosition = FormStartPosition.CenterParent;
    AutoSize = true;
    AutoSizeMode = AutoSizeMode.GrowAndShrink;

    width.Value = Math.Clamp(w, 1, 16384);
    height.Value = Math.Clamp(h, 1, 16384);
    presets.Items.Add("(custom)");
    foreach (Size s in Presets)
      presets.Items.Add($"{s.Width} x {s.Height}");
    presets.SelectedIndex = 0;
    presets.SelectedIndexChanged += (_, _) =>
    {
      if (presets.SelectedIndex > 0)
      {
        width.Value = Presets[presets.SelectedIndex - 1].Width;
        height.Value = Presets[presets.SelectedIndex - 1].Height;
      }
    };

    var ok = new Button { Text = "OK", DialogResult = DialogResult.OK, AutoSize = true };
    var cancel = new Button { Text = "Cancel", DialogResult = DialogResult.Cancel, AutoSize = true };
    AcceptButton = ok;
    CancelButton = cancel;

    var layout = new FlowLayoutPanel { Dock = DockStyle.Fill, AutoSize = true, Padding = new Padding(8), WrapContents = false };
    layout.Controls.Add(new Label { Text = "Width", AutoSize = true, Anchor = AnchorStyles.Left, TextAlign = ContentAlignment.MiddleLeft });
    layout.Controls.Add(width);
    layout.Controls.Add(new Label { Text = "Height", AutoSize = true, Anchor = AnchorStyles.Left, TextAlign = ContentAlignment.MiddleLeft });
    layout.Controls.Add(height);
    layout.Controls.Add(presets);
    layout.Controls.Add(ok);
    layout.Controls.Add(cancel);
    Controls.Add(layout);
  }

  public int ImageWidth => (int)width.Value;

  public int ImageHeight => (int)height.Value;
}
