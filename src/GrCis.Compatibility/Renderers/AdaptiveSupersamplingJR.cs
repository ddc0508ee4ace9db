using System;

namespace Rendering;

/// <summary>
/// GrCis's quad-tree adaptive supersampling: one jittered sample for the whole pixel, then the square
/// is split into four (the old sample kept in the quarter it fell into, the others sampled anew) for as
/// long as neighbouring quarters hit different objects (different hashes) or differ in colour by
/// <see cref="colorThreshold"/> or more (RGB distance), down to cells of 1/<see cref="SupersamplingImageSynthesizer.SuperXY"/>.
/// The pixel is the area-weighted mean of the leaves. Sampling goes through <see cref="MT"/>, so a
/// pixel is the same whatever the threads.
/// </summary>
public class AdaptiveSupersamplingJR : SupersamplingImageSynthesizer
{
  protected int bands;

  protected double colorThreshold;

  public AdaptiveSupersamplingJR(double colThreshold = 0.004) : base(16) => colorThreshold = colThreshold;

  /// <summary>A square of the pixel: its corner, side, one sample inside it, or four children.</summary>
  sealed class Cell
  {
    public readonly double X, Y, Step;
    public Cell[]? Children;
    public Sample? Sample;

    public Cell(double x, double y, double step) => (X, Y, Step) = (x, y, step);
  }

  sealed record Sample(double X, double Y, double[] Color, long Hash);

  Sample Take(Cell cell)
  {
    double sx = cell.X + cell.Step * MT.rnd.UniformNumber();
    double sy = cell.Y + cell.Step * MT.rnd.UniformNumber();
    double[] color = new double[bands];
    long hash = Function.GetSample(sx, sy, color);
    MT.NextSample();
    return new Sample(sx, sy, color, hash);
  }

  bool Differ(Sample a, Sample b)
  {
    if (a.Hash != b.Hash)
      return true;
    double sum = 0.0;
    for (int i = 0; i < Math.Min(3, bands); i++)
      sum += (a.Color[i] - b.Color[i]) * (a.Color[i] - b.Color[i]);
    return Math.Sqrt(sum) >= colorThreshold;
  }

  void Subdivide(Cell cell, int division, int maxDivision)
  {
    double half = cell.Step * 0.5;
    var ch = new Cell[4]
    {
      new(cell.X, cell.Y, half), new(cell.X, cell.Y + half, half),
      new(cell.X + half, cell.Y, half), new(cell.X + half, cell.Y + half, half),
    };
    cell.Children = ch;
    // The parent's sample stays with the quarter it lies in; the others get new samples (in order).
    Sample? old = cell.Sample;
    cell.Sample = null;
    foreach (Cell c in ch)
    {
      if (old != null && old.X < c.X + half && old.Y < c.Y + half && old.X >= c.X && old.Y >= c.Y)
      {
        c.Sample = old;
        old = null;
      }
      else
        c.Sample = Take(c);
    }

    if ((division *= 2) >= maxDivision)
      return;
    bool s0 = false, s1 = false, s2 = false, s3 = false;
    if (Differ(ch[0].Sample!, ch[1].Sample!)) s0 = s1 = true;
    if (Differ(ch[1].Sample!, ch[3].Sample!)) s1 = s3 = true;
    if (Differ(ch[0].Sample!, ch[2].Sample!)) s0 = s2 = true;
    if (Differ(ch[2].Sample!, ch[3].Sample!)) s2 = s3 = true;
    if (s0) Subdivide(ch[0], division, maxDivision);
    if (s1) Subdivide(ch[1], division, maxDivision);
    if (s2) Subdivide(ch[2], division, maxDivision);
    if (s3) Subdivide(ch[3], division, maxDivision);
  }

  static void Gather(Cell cell, double[] color)
  {
    if (cell.Children != null)
    {
      foreach (Cell c in cell.Children)
        Gather(c, color);
      return;
    }
    double area = cell.Step * cell.Step;
    for (int b = 0; b < color.Length; b++)
      color[b] += area * cell.Sample!.Color[b];
  }

  public override void RenderPixelLinear(int x, int y, double[] color)
  {
    MT.StartPixel(x, y, Supersampling);
    bands = color.Length;
    var root = new Cell(x, y, 1.0);
    root.Sample = Take(root);
    if (superXY > 1)
      Subdivide(root, 1, superXY);
    Array.Clear(color);
    Gather(root, color);
  }
}
