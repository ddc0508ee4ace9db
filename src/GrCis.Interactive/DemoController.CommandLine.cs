using System;
using System.Collections.Generic;

namespace GrCis.Interactive;

// DemoController's start from GrCis's command line (-dir, -scene, -nodefault, -render-to).
public sealed partial class DemoController
{
  /// <summary>
  /// The demo as GrCis starts it from its command line (<c>-dir</c>, <c>-scene</c>, <c>-nodefault</c>):
  /// the built-in scenes unless <c>-nodefault</c>, then the scripts; the first <c>-scene</c> file (else
  /// the first script of the <c>-dir</c> folders, else GrCis's default scene) selected. Unknown options and missing files or folders go to
  /// <paramref name="problems"/> as messages for the user; everything else is still loaded.
  /// </summary>
  /// <param name="scripts">Compiles and runs the scene scripts (<see cref="SceneCatalog.Scripts"/>); null = built-in scenes only.</param>
  /// <param name="allowScript">The script files this front end may open (<see cref="SceneCatalog.AllowScript"/>); null = any.</param>
  public static DemoController FromCommandLine(IReadOnlyList<string> args, GrCis.Scripting.ScriptHost? scripts, ICollection<string> problems,
                                               Predicate<string>? allowScript = null)
  {
    ArgumentNullException.ThrowIfNull(args);
    ArgumentNullException.ThrowIfNull(problems);
    DemoCommandLine commandLine = DemoCommandLine.Parse(args);
    foreach (string e in commandLine.Errors)
      problems.Add(e);
    var catalog = new SceneCatalog(scripts) { AllowScript = allowScript };
    SceneEntry? first = catalog.AddFromCommandLine(commandLine, problems);
    return new DemoController(catalog) { Selected = first, RenderTo = commandLine.RenderTo };
  }
}
