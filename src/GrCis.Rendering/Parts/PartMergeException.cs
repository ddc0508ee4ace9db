using System;

namespace Rendering.Parts;

/// <summary>A set of parts that does not make one image (incomplete, overlapping or from different renders); nothing was written.</summary>
public sealed class PartMergeException : Exception
{
  /// <summary>A failed merge, with <paramref name="message"/> saying why.</summary>
  /// <param name="message">What is wrong with the set of parts.</param>
  public PartMergeException(string message) : base(message) { }
}
