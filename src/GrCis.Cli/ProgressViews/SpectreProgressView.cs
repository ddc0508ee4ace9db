using System;
using System.IO;
using Rendering.Execution;
using Spectre.Console;

namespace GrCis.Cli.ProgressViews;

/// <summary>A live progress bar (Spectre.Console) on a terminal, drawn on stderr so stdout stays clean.</summary>
public sealed class SpectreProgressView : IProgressView
{
  readonly IAnsiConsole console;

  public SpectreProgressView(TextWriter terminal)
  {
    console = AnsiConsole.Create(new AnsiConsoleSettings
    {
      Out = new AnsiConsoleOutput(terminal),
      Ansi = AnsiSupport.Detect,
      ColorSystem = ColorSystemSupport.Detect,
      Interactive = InteractionSupport.Yes,
    });
  }

  public T Run<T>(string title, Func<Action<RenderProgress>, T> work) =>
    console.Progress()
      .AutoClear(true)
      .HideCompleted(false)
      .Columns(
        new TaskDescriptionColumn(),
        new ProgressBarColumn(),
        new PercentageColumn(),
        new ElapsedTimeColumn(),
        new RemainingTimeColumn(),
        new SpinnerColumn())
      .Start(ctx =>
      {
        ProgressTask task = ctx.AddTask(Markup.Escape(title), maxValue: 1.0);
        T result = work(p =>
        {
          task.MaxValue = p.TilesTotal;
          task.Value = p.TilesDone;
        });
        task.StopTask();
        return result;
      });
}
