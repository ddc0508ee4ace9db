using System;
using System.Collections.Generic;

namespace GrCis.Interactive;

/// <summary>
/// The demo's command line as GrCis has it: <c>-dir DIR</c>, <c>-scene FILE</c> (both repeatable), <c>-nodefault</c>;
/// and ours, <c>-render-to FILE</c>: render the selected scene as the Render button does, save the PNG, close.
/// </summary>
public sealed class DemoCommandLine
{
  public List<string> Directories { get; } = new();

  public List<string> SceneFiles { get; } = new();

  /// <summary>Render the selected scene at start, save it here (PNG) and close: smoke tests and batch use of the window.</summary>
  public string? RenderTo { get; private set; }

  /// <summary>Leave the built-in scenes out of the list.</summary>
  public bool NoDefault { get; private set; }

  /// <summary>Problems found while parsing, one message each (unknown switch, missing value).</summary>
  public List<string> Errors { get; } = new();

  public static DemoCommandLine Parse(IReadOnlyList<string> args)
  {
    ArgumentNullException.ThrowIfNull(args);
    var cl = new DemoCommandLine();
    for (int i = 0; i < args.Count; i++)
    {
      string a = args[i];
      // GrCis accepts both "-dir" and "--dir"; we do too.
      string key = a.TrimStart('-').ToLowerInvariant();
      if (!a.StartsWith('-'))
      {
        // A bare path is a scene script (handy for "open with").
        cl.SceneFiles.Add(a);
        continue;
      }
      switch (key)
      {
        case "nodefault":
          cl.NoDefault = true;
          break;
        case "dir":
        case "scene":
        case "render-to":
          if (i + 1 >= args.Count)
          {
            cl.Errors.Add($"{a} needs a path after it.");
            break;
          }
          string value = args[++i];
          if (key == "render-to")
            cl.RenderTo = value;
          else
            (key == "dir" ? cl.Directories : cl.SceneFiles).Add(value);
          break;
        default:
          cl.Errors.Add($"Unknown option {a}; known are -dir DIR, -scene FILE, -nodefault, -render-to FILE.");
          break;
      }
    }
    return cl;
  }
}
