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
      With(s, kind, (v, k) => Results.Bytes(Text(w => v.WriteCsv(k, w)), "text/csv", $"{kind.ToLowerInvariant()}.csv")));
    app.MapGet("/api/views/points.ply", (StudioSession s) =>
      s.Views is ExtraViews v
        ? Results.Bytes(Text(w => v.WritePointCloud(w, s.FinalImage(), s.Controller.LastResult?.Gamma ?? 1.0)), "application/octet-stream", "points.ply")
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

  // The bytes the window's export writes to a file: UTF-8 without a byte-order mark, "\n" line ends.
  static byte[] Text(Action<TextWriter> write)
  {
    using var bytes = new MemoryStream();
    using (var w = new StreamWriter(bytes, new System.Text.UTF8Encoding(false)) { NewLine = "\n" })
      write(w);
    return bytes.ToArray();
  }
}
