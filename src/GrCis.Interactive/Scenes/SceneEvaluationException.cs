using System;

namespace GrCis.Interactive;

/// <summary>A scene could not be built (script error, missing file); the message is meant for the user.</summary>
public sealed class SceneEvaluationException : Exception
{
  public SceneEvaluationException(string message) : base(message) { }

  public SceneEvaluationException(string message, Exception inner) : base(message, inner) { }
}
