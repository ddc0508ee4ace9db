using GrCis.Hosting;
using GrCis.Hosting.Export;
using GrCis.Interactive;
using Rendering;
using Rendering.Execution;
using Rendering.Tessellation;

namespace GrCis.Studio;

/// <summary>
/// The scene on show as a glTF binary (<c>.glb</c>), as <c>grcis export</c> writes it: the last still render's scene at
/// the time it was rendered, or an animation frame's scene at the frame's time.
/// </summary>
internal static class StudioSceneFiles
{
  /// <summary>The last still render's scene, or null before the first render.</summary>
  public static byte[]? StillGlb(StudioSession s)
  {
    RenderJob? job = s.Controller.LastJob;
    if (job == null)
      return null;
    return Glb(job.Scene, job, job.SceneName ?? "scene");
  }

  /// <summary>Frame <paramref name="k"/>'s scene of the animation on show, or null when there is none or no such frame.</summary>
  public static byte[]? FrameGlb(StudioSession s, int k)
  {
    if (s.Animation?.Run is not AnimationRun run || k < 0 || k >= run.Timeline.FrameCount)
      return null;
    // A copy of the scene's moving parts, moved to the frame's time; the run's own scene is left as the run uses it.
    IRayScene scene = SceneCloner.CloneForWorker(run.Job.Scene);
    if (SceneCloner.IsTimeDependent(scene))
      SceneTime.Set(scene, run.Timeline.FrameTime(k));
    return Glb(scene, run.Job, $"{run.Job.SceneName ?? "scene"} frame {k}");
  }

  static byte[] Glb(IRayScene scene, RenderJob job, string name)
  {
    var options = new TessellationOptions { Width = job.Settings.Width, Height = job.Settings.Height };
    return GltfWriter.ToGlb(SceneTessellator.Tessellate(scene, options), name);
  }
}
