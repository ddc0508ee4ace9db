using System;
using Rendering.Tessellation;

namespace GrCis.Hosting.Export;

/// <summary>
/// The scene of a render request as a <see cref="SceneTessellation"/>: built as a render builds it (the script run with
/// its parameters, the settings resolved, an animated scene set to the requested time), the camera at the image size
/// the render would have.
/// </summary>
public static class SceneExport
{
  /// <summary>Builds the scene of <paramref name="request"/> and tessellates it.</summary>
  /// <exception cref="GrCis.Scripting.ScriptCompilationException">The script or a module did not compile.</exception>
  /// <exception cref="GrCis.Scripting.ScriptRuntimeException">The script threw.</exception>
  public static SceneTessellation Tessellate(RenderRequest request, Func<Setting, string>? name = null) =>
    Tessellate(request.Prepare(name));

  /// <summary>Tessellates a prepared scene (its time already set) with the camera at the resolved image size.</summary>
  public static SceneTessellation Tessellate(PreparedRender prepared)
  {
    ArgumentNullException.ThrowIfNull(prepared);
    var options = new TessellationOptions { Width = prepared.Settings.Width, Height = prepared.Settings.Height };
    return SceneTessellator.Tessellate(prepared.Scene, options);
  }
}
