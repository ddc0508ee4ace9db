using System;

namespace GrCis.Scripting.Tests;

/// <summary>Tests that write scripts and modules into a scratch folder and compile them with one host of their own.</summary>
public abstract class ScratchScriptTests : IDisposable
{
  protected ScratchScriptTests(string prefix) => scratch = new ScratchFolder(prefix);

  protected readonly ScratchFolder scratch;
  protected readonly ScriptHost host = new();

  /// <summary>Writes <paramref name="text"/> to <paramref name="relative"/> in the scratch folder; returns the full path.</summary>
  protected string Write(string relative, string text) => scratch.Write(relative, text);

  public void Dispose()
  {
    host.Dispose();
    scratch.Dispose();
    GC.SuppressFinalize(this);
  }
}
