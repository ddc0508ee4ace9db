using GrCis.Hosting;
using Rendering.Tessellation;

namespace GrCis.Studio;

/// <summary>
/// The last still render's scene as triangles and its part index, made once per render job: the 3D view, every probe
/// (which part its ray hit) and the hit points ask for them, and a large mesh is not tessellated again for each.
/// </summary>
internal sealed class StillScene
{
  readonly object sync = new();
  RenderJob? job;
  SceneTessellation? tessellation;
  SceneParts? parts;

  /// <summary>The tessellation of <paramref name="of"/>'s scene (at its render's size) and its parts.</summary>
  public (SceneTessellation Tessellation, SceneParts Parts) For(RenderJob of)
  {
    lock (sync)
    {
      if (!ReferenceEquals(job, of) || tessellation == null || parts == null)
      {
        tessellation = StudioSceneFiles.Tessellate(of.Scene, of);
        parts = new SceneParts(tessellation);
        job = of;
      }
      return (tessellation, parts);
    }
  }
}
