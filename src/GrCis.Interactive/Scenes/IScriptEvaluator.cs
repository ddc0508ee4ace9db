using System.Collections.Generic;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// Runs a scene script (the Roslyn host in GrCis.Scripting implements this through an adapter).
/// The script fills <paramref name="scene"/> and may read and write GrCis context keys
/// (<see cref="PropertyName.CTX_WIDTH"/>, …) in <paramref name="context"/>.
/// </summary>
public interface IScriptEvaluator
{
  /// <exception cref="SceneEvaluationException">The script does not compile or throws; the message names file and line.</exception>
  void Run(string path, string source, IRayScene scene, string param, Dictionary<string, object?> context);
}
