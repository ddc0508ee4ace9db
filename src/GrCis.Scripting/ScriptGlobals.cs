using System.Collections.Generic;
using Rendering;

namespace GrCis.Scripting;

/// <summary>
/// The variables a scene script sees as globals. The field names (lower case) are GrCis's
/// and part of the script contract.
/// </summary>
public class ScriptGlobals
{
  /// <summary>The scene the script fills (intersectable, camera, lights, background).</summary>
  public IRayScene scene;

  /// <summary>Free text from the user, usually <c>key=value, key2</c> pairs.</summary>
  public string param;

  /// <summary>In/out values shared by the calls of one batch (see <see cref="PropertyName"/> CTX_*).</summary>
  public Dictionary<string, object> context;

  public ScriptGlobals(IRayScene scene, string? param, Dictionary<string, object> context)
  {
    this.scene = scene;
    this.param = param ?? "";
    this.context = context;
  }
}
