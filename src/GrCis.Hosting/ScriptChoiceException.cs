using System;

namespace GrCis.Hosting;

/// <summary>A scene script asked for a value no render can use (an image size of −5, supersampling 0).</summary>
public sealed class ScriptChoiceException : Exception
{
  public ScriptChoiceException(string message) : base(message)
  {
  }
}
