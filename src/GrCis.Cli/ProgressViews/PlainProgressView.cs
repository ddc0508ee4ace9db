using System;
using System.IO;
using Rendering.Execution;

namespace GrCis.Cli.ProgressViews;

/// <summary>Progress for logs and pipes: one line per 10 % step, e.g. <c>render: 40% (48/120 tiles)</c>.</summary>
public sealed class PlainProgressView : IProgressView
{
  readonly TextWriter writer;

  public PlainProgressView(TextWriter writer) => this.writer = writer;

  public T Run<T>(string title, Func<Action<RenderProgress>, T> work)
  {
    int lastDecile = 0;
    writer.WriteLine($"{title}: started");
    return work(p =>
    {
      // Callbacks are serialized by the tile renderer.
      int decile = (int)(p.Fraction * 10.0 + 1e-9);
      if (decile <= lastDecile)
        return;
      lastDecile = decile;
      writer.WriteLine($"{title}: {decile * 10}% ({p.TilesDone}/{p.TilesTotal} tiles)");
      writer.Flush();
    });
  }
}
