using System;

namespace GrCis.Hosting;

/// <summary>The render ended (finished, stopped or failed).</summary>
public sealed class RenderCompletedEventArgs : EventArgs
{
  public RenderCompletedEventArgs(RenderResult result) => Result = result;

  public RenderResult Result { get; }
}
