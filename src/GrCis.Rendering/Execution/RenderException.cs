using System;

namespace Rendering.Execution;

/// <summary>A failure inside the scene while rendering (a solid, texture or script threw).</summary>
public sealed class RenderException : Exception
{
  public RenderException(string message, Exception inner) : base(message, inner) { }
}
