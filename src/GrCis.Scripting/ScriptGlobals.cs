using System.Collections.Generic;
using Rendering;

namespace GrCis.Scripting;

/// <summary>
/// The variables a scene script sees as globals. The field names (lower case) are GrCis's and part of
/// the script contract. GrCis renamed them over the years and students keep the names of the year they
/// forked, so every year's name is here: <c>scene</c>, <c>param</c> and <c>context</c> (today's), and
/// <c>sc</c> (March 2018), <c>sceneName</c> (2018 to 2020), <c>outParam</c> (2018 to 2020, the dictionary
/// that became <c>context</c>), <c>scriptFilePath</c> (May 2020, first proposed as <c>scriptFileName</c>). The old names are the same objects as
/// the new ones; a script's own variable of the same name hides the global, as any outer name.
/// </summary>
public class ScriptGlobals
{
  /// <summary>The scene the script fills (intersectable, camera, lights, background).</summary>
  public IRayScene scene;

  /// <summary>Free text from the user, usually <c>key=value, key2</c> pairs.</summary>
  public string param;

  /// <summary>In/out values shared by the calls of one batch (see <see cref="PropertyName"/> CTX_*).</summary>
  public Dictionary<string, object> context;

  /// <summary>GrCis's first name of <see cref="scene"/> (March 2018).</summary>
  public IRayScene sc;

  /// <summary>The scene's name, as <see cref="PropertyName.CTX_SCENE_NAME"/> holds it when the script starts.</summary>
  public string sceneName;

  /// <summary>GrCis's name of <see cref="context"/> from 2018 to 2020: the same dictionary.</summary>
  public Dictionary<string, object> outParam;

  /// <summary>Full path of the script file (GrCis's global of May 2020; also <see cref="PropertyName.CTX_SCRIPT_PATH"/>).</summary>
  public string scriptFilePath;

  /// <summary>
  /// The same path under the name it had in the pull request that brought it to GrCis (May 2020); scripts of
  /// the students who worked on that branch use it.
  /// </summary>
  public string scriptFileName => scriptFilePath;

  public ScriptGlobals(IRayScene scene, string? param, Dictionary<string, object> context)
  {
    this.scene = scene;
    this.param = param ?? "";
    this.context = context;
    sc = scene;
    outParam = context;
    sceneName = context.TryGetValue(PropertyName.CTX_SCENE_NAME, out object? name) && name is string s ? s : "";
    scriptFilePath = context.TryGetValue(PropertyName.CTX_SCRIPT_PATH, out object? path) && path is string p ? p : "";
  }
}
