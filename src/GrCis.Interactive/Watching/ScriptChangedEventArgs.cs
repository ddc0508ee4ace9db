using System;

namespace GrCis.Interactive;

public sealed class ScriptChangedEventArgs : EventArgs
{
  public ScriptChangedEventArgs(string path) => Path = path;

  public string Path { get; }
}
