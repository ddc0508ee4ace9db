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

  /// <summary>A problem at line <paramref name="lineNumber"/> of <paramref name="fileName"/>; the message reads <c>fileName(lineNumber): problem</c>.</summary>
  /// <param name="fileName">The file (or stream name) being read.</param>
  /// <param name="lineNumber">1-based line number of the offending line.</param>
  /// <param name="problem">What is wrong, without the location.</param>
  /// <param name="inner">The exception that revealed the problem, or null.</param>
  public MeshFormatException(string fileName, int lineNumber, string problem, Exception? inner = null)
    : base($"{fileName}({lineNumber}): {problem}", inner)
  {
    FileName = fileName;
    LineNumber = lineNumber;
    Problem = problem;
  }
}
