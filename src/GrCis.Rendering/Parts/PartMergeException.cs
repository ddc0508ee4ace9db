using System;

namespace Rendering.Parts;

/// <summary>A set of parts that does not make one image (incomplete, overlapping or from different renders); nothing was written.</summary>
public sealed class PartMergeException : Exception
{
  public PartMergeException(string message) : base(message) { }
}
