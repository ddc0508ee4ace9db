using System;

namespace Rendering.Execution;

/// <summary>
/// User code recursed deeper than <see cref="Recursion.MaxDepth"/> calls, or until the thread's stack was nearly full
/// (thrown by <see cref="Recursion.Enter"/>, on entry to the user method that went one call too deep).
/// </summary>
public sealed class RecursionTooDeepException : Exception
{
  /// <summary>The exception with <paramref name="message"/>, which says how deep the calls went.</summary>
  public RecursionTooDeepException(string message) : base(message)
  {
  }
}
