// What grcis gives every scene script, declared for the IDE and `dotnet build` (grcis itself does not read
// this file): the namespaces a script sees without `using`, and the globals, as static members brought in
// by `using static`. At render time grcis fills them; here they only have their types and comments.

global using System;
global using System.Diagnostics;
global using System.Collections.Generic;
global using OpenTK.Mathematics;
global using MathSupport;
global using Rendering;
global using Utilities;
global using Scene3D;
global using Rendering.Distributed;
global using static GrCisScript.ScriptGlobals;

namespace GrCisScript;

/// <summary>The globals of a GrCis scene script (GrCis.Scripting.ScriptGlobals when grcis runs it).</summary>
public static class ScriptGlobals
{
  /// <summary>The scene the script fills (intersectable, camera, lights, background).</summary>
  public static IRayScene scene;

  /// <summary>Free text from the user (grcis --param), usually <c>key=value, key2</c> pairs.</summary>
  public static string param;

  /// <summary>In/out values shared by the calls of one batch (keys <c>PropertyName.CTX_*</c>).</summary>
  public static Dictionary<string, object> context;

  /// <summary>GrCis's first name of <see cref="scene"/> (March 2018).</summary>
  public static IRayScene sc;

  /// <summary>The scene's name (the script's file name for grcis).</summary>
  public static string sceneName;

  /// <summary>GrCis's name of <see cref="context"/> from 2018 to 2020: the same dictionary.</summary>
  public static Dictionary<string, object> outParam;

  /// <summary>Full path of the script file (also <c>context[PropertyName.CTX_SCRIPT_PATH]</c>).</summary>
  public static string scriptFilePath;

  /// <summary>The same path under its name in GrCis's pull request of May 2020.</summary>
  public static string scriptFileName => scriptFilePath;
}
