using System;
using GrCis.Editing;

namespace GrCis.Editing.Tests;

/// <summary>One assistant for a test class: its workspace loads the references' metadata once.</summary>
public sealed class AssistantFixture : IDisposable
{
  public ScriptAssistant Assistant { get; } = new();

  public void Dispose() => Assistant.Dispose();
}
