// What grcis gives every scene script, declared for the IDE and `dotnet build` (grcis itself does not read
// this file): the namespaces a script sees without `using`, and the globals, as static members brought in
// by `using static`. At render time grcis fills them.
//
// `dotnet run` here runs Scene.cs as a program: the globals get what grcis would give (an empty scene, the
// command line's words as param: dotnet run -- "radius=1.2"), and when the script is done the scene is rendered
// to scene.png for a quick look (Whitted ray tracing, the script's size and supersampling, else 640x480 and one
// sample per pixel). grcis render Scene.cs renders it with all of grcis's settings.

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
  // The first use of a global (the script's first statement) gives them their values.
  static ScriptGlobals()
  {
    scene = sc = new AnimatedRayScene();
    string[] args = Environment.GetCommandLineArgs();
    param = string.Join(" ", args, 1, args.Length - 1);
    context = outParam = new Dictionary<string, object>();
    scriptFilePath = System.IO.Path.GetFullPath("Scene.cs");
    sceneName = "Scene";
    context[PropertyName.CTX_SCRIPT_PATH] = scriptFilePath;
    AppDomain.CurrentDomain.ProcessExit += (_, _) => RenderForDotnetRun("scene.png");
  }

  /// <summary>What <c>dotnet run</c> does after the script: renders the scene it built to <paramref name="file"/>.</summary>
  static void RenderForDotnetRun(string file)
  {
    if (scene.Intersectable == null || scene.Camera == null)
    {
      Console.Error.WriteLine("Scene.cs set no scene.Intersectable or no scene.Camera: nothing to render.");
      Environment.ExitCode = 1;
      return;
    }
    int width = context.TryGetValue(PropertyName.CTX_WIDTH, out object w) && w is int wi && wi > 0 ? wi : 640;
    int height = context.TryGetValue(PropertyName.CTX_HEIGHT, out object h) && h is int hi && hi > 0 ? hi : 480;
    int spp = context.TryGetValue(PropertyName.CTX_SUPERSAMPLING, out object n) && n is int ni && ni > 0 ? ni : 1;
    if (scene is ITimeDependent animated)
      animated.Time = animated.Start;
    Rendering.Imaging.FloatImage image = Rendering.Execution.TileRenderer.Render(scene,
      Rendering.Execution.RenderSetup.CreateRayTracing(scene, true, true, true),
      Rendering.Execution.RenderSetup.CreateSynthesizer(width, height, spp, 1.0), new Rendering.Execution.RenderOptions());
    Rendering.Imaging.PngFile.Save(file, Rendering.Execution.RenderSetup.ToDisplayImage(image));
    Console.WriteLine($"Rendered {System.IO.Path.GetFullPath(file)} ({width}x{height}, {spp} sample(s) per pixel, Whitted ray tracing).");
    Console.WriteLine("For grcis's full render (the script's algorithm, --param, --size, --spp, animation): grcis render Scene.cs -o scene.png");
  }

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
