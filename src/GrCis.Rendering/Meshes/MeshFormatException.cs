using System;

namespace Rendering;

/// <summary>A malformed mesh file; the message reads <c>path(line): what is wrong</c>.</summary>
public class MeshFormatException : FormatException
{
  /// <summary>The file (or stream name) being read.</summary>
  public string FileName { get; }

  /// <summary>1-based line number of the offending line.</summary>
  public int LineNumber { get; }

  /// <summary>What is wrong, without the location.</summary>
  public string Problem { get; }

  public MeshFormatException(string fileName, int lineNumber, string problem, Exception? inner = null)
    : base($"{fileName}({lineNumber}): {problem}", inner)
  {
    FileName = fileName;
    LineNumber = lineNumber;
    Problem = problem;
  }
}
