using System;

namespace GrCis.Bench.Embree;

/// <summary>Intel Embree's shared library is not installed; the message names the Debian package.</summary>
public sealed class EmbreeMissingException : Exception
{
  /// <summary>An exception with the one-line message shown to the user.</summary>
  public EmbreeMissingException(string message) : base(message) { }
}
