using System;

namespace GrCis.Bench.Plots;

/// <summary>A plot input that cannot be read: the message names the file and, where there is one, the line.</summary>
public sealed class PlotInputException(string file, int line, string message)
  : Exception(line > 0 ? $"{file}:{line}: {message}" : $"{file}: {message}");
