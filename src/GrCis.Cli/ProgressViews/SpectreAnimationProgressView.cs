using System;
using System.IO;
using GrCis.Cli.Animation;
using Spectre.Console;

namespace GrCis.Cli.ProgressViews;

/// <summary>A live bar of frames done (Spectre.Console) on a terminal, drawn on stderr.</summary>
public sealed class SpectreAnimationProgressView : IAnimationProgressView
{
  readonly IAnsiConsole console;

  public SpectreAnimationProgressView(TextWriter terminal)
  {
    console = AnsiConsole.Create(new AnsiConsoleSettings
    {
      Out = new AnsiConsoleOutput(terminal),
      Ansi = AnsiSupport.Detect,
      ColorSystem = ColorSystemSupport.Detect,
      Interactive = InteractionSupport.Yes,
    });
  }

  public T Run<T>(string title, int framesTotal, int framesSkipped, Func<Action<AnimationProgress>, T> work) =>
    console.Progress()
      .AutoClear(false)
      .HideCompleted(false)
      .Columns(
        new TaskDescriptionColumn { Alignment = Justify.Left },
        new ProgressBarColumn(),
        new PercentageColumn(),
        new ElapsedTimeColumn(),
        new SpinnerColumn())
      .Start(ctx =>
      {
        string name = Markup.Escape(title);
        ProgressTask task = ctx.AddTask($"{name} {framesSkipped}/{framesTotal} frames", maxValue: Math.Max(1, framesTotal));
        task.Value = framesSkipped;
        T result = work(p =>
        {
          task.Value = p.FramesDone;
          task.Description = $"{name} {Markup.Escape(AnimationProgressText.Of(p))}";
        });
        task.StopTask();
        return result;
      });
}
