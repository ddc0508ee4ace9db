using System;
using System.Drawing;
using System.Windows.Forms;
using GrCis.Interactive;

namespace GrCis.Demo.WinForms;

/// <summary>The clicked pixel in full: colour, hash and the tree of its rays.</summary>
sealed class ProbeForm : Form
{
  readonly TextBox text = new()
  {
    Dock = DockStyle.Fill,
    Multiline = true,
    ReadOnly = true,
    WordWrap = false,
    ScrollBars = ScrollBars.Both,
    Font = MonospaceFont(),
  };

  public ProbeForm()
  {
    Text = "Pixel rays";
    ClientSize = new Size(720, 320);
    StartPosition = FormStartPosition.Manual;
    ShowInTaskbar = false;
    Controls.Add(text);
  }

  static Font MonospaceFont()
  {
    try
    {
      return new Font(FontFamily.GenericMonospace, 9f);
    }
    catch (ArgumentException)
    {
      // No monospace font installed (seen under Wine without fonts): the default font still reads.
      return Control.DefaultFont;
    }
  }

  public void Show(ProbeResult probe)
  {
    Text = $"Pixel [{probe.X},{probe.Y}]";
    text.Text = probe.ToString().Replace("\n", "\r\n");
  }
}
