using GrCis.Hosting;
using GrCis.Hosting.Export;
using GrCis.Interactive;
using Rendering;
using Rendering.Execution;
using Rendering.Tessellation;

namespace GrCis.Studio;

/// <summary>
/// The scene on show as triangles: the last still render's scene at the time it was rendered, or an animation frame's
/// scene at the frame's time; as a glTF binary (<c>.glb</c>, what <c>grcis export</c> writes) or as the page's 3D view
/// reads it (<see cref="SceneView3d"/>).
/// </summary>
internal static class StudioSceneFiles
{
  /// <summary>The last still render's scene as glTF, or null before the first render.</summary>
  public static byte[]? StillGlb(StudioSession s) =>
    Still(s) is var (tessellation, _, name) ? GltfWriter.ToGlb(tessellation, name) : null;

  /// <summary>Frame <paramref name="k"/>'s scene of the animation on show as glTF, or null when there is none or no such frame.</summary>
  public static byte[]? FrameGlb(StudioSession s, int k) =>
    Frame(s, k) is var (tessellation, _, name) ? GltfWriter.ToGlb(tessellation, name) : null;

  /// <summary>The last still render's scene, its render's settings and a name; null before the first render.</summary>
  public static (SceneTessellation Tessellation, RenderSettings Settings, string Name)? Still(StudioSession s)
  {
    RenderJob? job = s.Controller.LastJob;
    if (job == null)
      return null;
    return (s.StillScene.For(job).Tessellation, job.Settings, job.SceneName ?? "scene");
  }

  /// <summary>Frame <paramref name="k"/>'s scene of the animation on show, its run's settings and a name; null when there is none or no such frame.</summary>
  public static (SceneTessellation Tessellation, RenderSettings Settings, string Name)? Frame(StudioSession s, int k)
  {
    if (s.Animation?.Run is not AnimationRun run || k < 0 || k >= run.Timeline.FrameCount)
      return null;
    // A copy of the scene's moving parts, moved to the frame's time; the run's own scene is left as the run uses it.
    IRayScene scene = SceneCloner.CloneForWorker(run.Job.Scene);
    if (SceneCloner.IsTimeDependent(scene))
      SceneTime.Set(scene, run.Timeline.FrameTime(k));
    return (Tessellate(scene, run.Job), run.Job.Settings, $"{run.Job.SceneName ?? "scene"} frame {k}");
  }

  /// <summary>The scene as triangles at <paramref name="job"/>'s image size (its camera's aspect ratio).</summary>
  internal static SceneTessellation Tessellate(IRayScene scene, RenderJob job) =>
    SceneTessellator.Tessellate(scene, new TessellationOptions { Width = job.Settings.Width, Height = job.Settings.Height });
}
