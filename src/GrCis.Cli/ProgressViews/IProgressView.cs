using System;
using Rendering.Execution;

namespace GrCis.Cli.ProgressViews;

/// <summary>Shows the progress of a render while <c>work</c> runs; <c>work</c> receives the callback to report tiles to.</summary>
public interface IProgressView
{
  T Run<T>(string title, Func<Action<RenderProgress>, T> work);
}
