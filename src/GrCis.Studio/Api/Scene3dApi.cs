using GrCis.Hosting;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;

namespace GrCis.Studio;

/// <summary>
/// The scene on show for the page's 3D view: its triangles, lights and camera (<c>/scene/tessellation</c>,
/// <see cref="SceneView3d"/>) and the points where the render's primary rays hit (<c>/scene/points</c>,
/// <see cref="HitPointCloud"/>), whose parts are the tessellation's.
/// </summary>
internal static class Scene3dApi
{
  /// <summary>The most points <c>/scene/points</c> gives (a 500 × 500 grid, 6 MB of JSON); the page asks for 40,000.</summary>
  public const int MaxPoints = 250_000;

  /// <summary>
  /// The primary rays' hits of the render on show: the image's size, the grid's step in pixels, the rays cast, the
  /// render's gamma (its image shows a linear value v as v^(1/gamma)), and per hit its world position (x, y, z, …,
  /// GrCis's world), its pixel's linear colour (r, g, b, …) and the index of the part it hit in the tessellation's parts
  /// (−1: a solid the view does not show).
  /// </summary>
  internal sealed record PointsJson(int Width, int Height, int Step, int Rays, double Gamma, int Count, float[] Positions, float[] Colors, int[] Parts);

  public static void MapScene3dApi(this IEndpointRouteBuilder api)
  {
    // Triangles, lights and camera as JSON (SceneView3d); ?frame=k an animation frame's.
    api.MapGet("/scene/tessellation", Tessellation);
    api.MapGet("/scene/points", Points);
  }

  static Results<Ok<SceneView3d.SceneJson>, ProblemHttpResult> Tessellation(StudioSession s, int? frame)
  {
    if (frame is int k)
      return StudioSceneFiles.Frame(s, k) is var (t, settings, name)
        ? TypedResults.Ok(SceneView3d.Of(t, settings, name))
        : Problems.NotFound($"no frame {k} in the animation on show");
    return StudioSceneFiles.Still(s) is var (still, stillSettings, stillName)
      ? TypedResults.Ok(SceneView3d.Of(still, stillSettings, stillName))
      : Problems.NotFound("nothing rendered yet: render a scene, and its scene shows in 3D");
  }

  static Results<Ok<PointsJson>, ProblemHttpResult> Points(StudioSession s, int? max)
  {
    int most = max ?? 40_000;
    if (most < 1 || most > MaxPoints)
      return Problems.BadRequest($"max={most}: ask for 1 to {MaxPoints:N0} points");
    if (s.Controller.LastJob is not RenderJob job)
      return Problems.NotFound("nothing rendered yet: render a scene, and the points its rays hit show in 3D");
    SceneParts parts = s.StillScene.For(job).Parts;
    HitPointCloud cloud = HitPointCloud.Cast(job, most, s.Controller.LastResult?.Job == job ? s.Controller.LastResult.Image : null);

    int n = cloud.Points.Count;
    var positions = new float[3 * n];
    var colors = new float[3 * n];
    var indices = new int[n];
    for (int i = 0; i < n; i++)
    {
      HitPoint p = cloud.Points[i];
      (positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]) = ((float)p.Position.X, (float)p.Position.Y, (float)p.Position.Z);
      (colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]) = ((float)p.Color.X, (float)p.Color.Y, (float)p.Color.Z);
      indices[i] = parts.IndexOf(p.Solid) ?? -1;
    }
    return TypedResults.Ok(new PointsJson(job.Width, job.Height, cloud.Step, cloud.Rays, job.Settings.Gamma, n, positions, colors, indices));
  }
}
