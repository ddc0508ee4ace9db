using System;
using System.IO;
using System.Threading;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// The extra views of the last render (depth, normals, rays per pixel): computed on request after the render,
/// shown as PNG, read out per pixel, downloaded as PNG, CSV or a PLY point cloud.
/// </summary>
internal static class ViewsApi
{
  public static void Map(WebApplication app)
  {
    app.MapPost("/api/views", (StudioSession s, CancellationToken cancel) =>
    {
      try
      {
        ExtraViews views = s.ComputeViews(cancel);
        return Results.Ok(new { width = views.Width, height = views.Height, allRaysKnown = views.AllRaysKnown, kinds = Enum.GetNames<MapKind>() });
      }
      catch (InvalidOperationException e)
      {
        return Results.Conflict(new { error = e.Message });
      }
    });
    app.MapGet("/api/views/{kind}.png", (string kind, StudioSession s) =>
      With(s, kind, (v, k) => Results.Bytes(PngEncoder.Default.Encode(Rgb8Image.FromFloatImage(v.ToImage(k), 1.0)), "image/png")));
    app.MapGet("/api/views/{kind}.csv", (string kind, StudioSession s) =>
      With(s, kind, (v, k) => Results.Bytes(ViaFile(path => v.SaveCsv(k, path)), "text/csv", $"{kind.ToLowerInvariant()}.csv")));
    app.MapGet("/api/views/points.ply", (StudioSession s) =>
      s.Views is ExtraViews v
        ? Results.Bytes(ViaFile(path => v.SavePointCloud(path, s.FinalImage(), s.Controller.LastResult?.Gamma ?? 1.0)), "application/octet-stream", "points.ply")
        : Results.NotFound());
    app.MapGet("/api/views/value", (string kind, int x, int y, StudioSession s) =>
      With(s, kind, (v, k) => x < 0 || y < 0 || x >= v.Width || y >= v.Height
        ? Results.BadRequest(new { error = $"pixel [{x}, {y}] lies outside the {v.Width}x{v.Height} image" })
        : Results.Ok(new { text = v.Describe(k, x, y) })));
  }

  static IResult With(StudioSession s, string kind, Func<ExtraViews, MapKind, IResult> answer)
  {
    if (s.Views is not ExtraViews views)
      return Results.NotFound(new { error = "compute the extra views first" });
    return Enum.TryParse(kind, ignoreCase: true, out MapKind k) && Enum.IsDefined(k)
      ? answer(views, k)
      : Results.NotFound(new { error = $"no view '{kind}'; the views are {string.Join(", ", Enum.GetNames<MapKind>())}" });
  }

  // The views save through files (atomically, as the window does); a download reads one back.
  static byte[] ViaFile(Action<string> save)
  {
    string path = Path.Combine(Path.GetTempPath(), "grcis-studio-" + Guid.NewGuid().ToString("N"));
    try
    {
      save(path);
      return File.ReadAllBytes(path);
    }
    finally
    {
      File.Delete(path);
    }
  }
}
