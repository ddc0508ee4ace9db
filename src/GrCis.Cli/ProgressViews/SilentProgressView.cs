using System;
using Rendering.Execution;

namespace GrCis.Cli.ProgressViews;

/// <summary>No progress output (<c>--quiet</c>).</summary>
public sealed class SilentProgressView : IProgressView
{
  public T Run<T>(string title, Func<Action<RenderProgress>, T> work) => work(_ => { });
}
