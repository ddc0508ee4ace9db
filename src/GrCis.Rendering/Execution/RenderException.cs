using System;

namespace Rendering.Execution;

/// <summary>A failure inside the scene while rendering (a solid, texture or script threw).</summary>
public sealed class RenderException : Exception
{
  /// <summary>A render failure caused by <paramref name="inner"/>.</summary>
  /// <param name="message">What failed, for the user.</param>
  /// <param name="inner">The exception thrown inside the scene.</param>
  public RenderException(string message, Exception inner) : base(message, inner) { }
}
