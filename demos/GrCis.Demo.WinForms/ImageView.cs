using System;
using System.ComponentModel;
using System.Drawing;
using System.Drawing.Drawing2D;
using System.Windows.Forms;
using GrCis.Interactive;

namespace GrCis.Demo.WinForms;

/// <summary>
/// Shows a bitmap with zoom and pan (<see cref="ZoomPan"/>): mouse wheel zooms about the cursor,
/// right-drag pans, + and − zoom, R resets. A left click or a mouse move over the image reports the pixel.
/// </summary>
sealed class ImageView : Control
{
  Bitmap? image;
  Point? dragFrom;

  public ImageView()
  {
    SetStyle(ControlStyles.AllPaintingInWmPaint | ControlStyles.UserPaint | ControlStyles.OptimizedDoubleBuffer |
      ControlStyles.ResizeRedraw | ControlStyles.Selectable, true);
    TabStop = true;
    BackColor = Color.FromArgb(48, 48, 48);
    View.Changed += (_, _) => Invalidate();
  }

  [Browsable(false), DesignerSerializationVisibility(DesignerSerializationVisibility.Hidden)]
  public ZoomPan View { get; } = new();

  /// <summary>The bitmap shown; the view owns it and disposes the previous one.</summary>
  [Browsable(false), DesignerSerializationVisibility(DesignerSerializationVisibility.Hidden)]
  public Bitmap? Image
  {
    get => image;
    set
    {
      if (ReferenceEquals(image, value))
        return;
      image?.Dispose();
      image = value;
      Invalidate();
    }
  }

  /// <summary>Left click on a pixel of the image.</summary>
  public event EventHandler<PixelEventArgs>? PixelClicked;

  /// <summary>The mouse moved over a pixel of the image.</summary>
  public event EventHandler<PixelEventArgs>? PixelHovered;

  protected override void OnPaint(PaintEventArgs e)
  {
    e.Graphics.Clear(BackColor);
    if (image == null)
      return;
    e.Graphics.InterpolationMode = InterpolationMode.NearestNeighbor;
    e.Graphics.PixelOffsetMode = PixelOffsetMode.Half;
    (double x, double y, double w, double h) = View.ImageBounds(image.Width, image.Height);
    e.Graphics.DrawImage(image, new RectangleF((float)x, (float)y, (float)w, (float)h));
  }

  protected override void OnMouseWheel(MouseEventArgs e)
  {
    View.Wheel(e.X, e.Y, e.Delta / (double)SystemInformation.MouseWheelScrollDelta);
    base.OnMouseWheel(e);
  }

  protected override void OnMouseDown(MouseEventArgs e)
  {
    Focus();
    if (e.Button == MouseButtons.Right)
    {
      dragFrom = e.Location;
      Cursor = Cursors.SizeAll;
    }
    else if (e.Button == MouseButtons.Left && TryPixel(e.Location, out int x, out int y))
      PixelClicked?.Invoke(this, new PixelEventArgs(x, y));
    base.OnMouseDown(e);
  }

  protected override void OnMouseMove(MouseEventArgs e)
  {
    if (dragFrom is Point from)
    {
      View.Pan(e.X - from.X, e.Y - from.Y);
      dragFrom = e.Location;
    }
    else if (TryPixel(e.Location, out int x, out int y))
      PixelHovered?.Invoke(this, new PixelEventArgs(x, y));
    base.OnMouseMove(e);
  }

  protected override void OnMouseUp(MouseEventArgs e)
  {
    if (e.Button == MouseButtons.Right)
    {
      dragFrom = null;
      Cursor = Cursors.Default;
    }
    base.OnMouseUp(e);
  }

  protected override bool IsInputKey(Keys keyData) =>
    keyData is Keys.Add or Keys.Subtract or Keys.Oemplus or Keys.OemMinus or Keys.R || base.IsInputKey(keyData);

  protected override void OnKeyDown(KeyEventArgs e)
  {
    switch (e.KeyCode)
    {
      case Keys.Add:
      case Keys.Oemplus:
        View.ZoomAt(Width / 2.0, Height / 2.0, ZoomPan.Step);
        e.Handled = true;
        break;
      case Keys.Subtract:
      case Keys.OemMinus:
        View.ZoomAt(Width / 2.0, Height / 2.0, 1.0 / ZoomPan.Step);
        e.Handled = true;
        break;
      case Keys.R:
        View.Reset();
        e.Handled = true;
        break;
    }
    base.OnKeyDown(e);
  }

  protected override void Dispose(bool disposing)
  {
    if (disposing)
      Image = null;
    base.Dispose(disposing);
  }

  bool TryPixel(Point p, out int x, out int y)
  {
    x = y = 0;
    return image != null && View.TryPixelAt(p.X + 0.5, p.Y + 0.5, image.Width, image.Height, out x, out y);
  }
}
