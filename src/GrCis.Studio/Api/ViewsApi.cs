using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// The extra views of the last render (depth, normals, rays per pixel): computed on request after the render,
/// shown as PNG, read out per pixel, downloaded as PNG, CSV or a PLY point cloud.
/// </summary>
internal static class ViewsApi
{
  internal sealed record ViewsJson(int Width, int Height, bool AllRaysKnown, IReadOnlyList<string> Kinds);

  internal sealed record ValueJson(string Text);

  public static void MapViewsApi(this IEndpointRouteBuilder api)
  {
    api.MapPost("/views", async Task<Results<Ok<ViewsJson>, ProblemHttpResult>> (StudioSession s, CancellationToken cancel) =>
    {
      // A render that has ended, or was stopped, is let finish first: the views are of its scene and image.
      if (!await s.Controller.SettleAsync())
        return Problems.NotSettled(s.Controller, GrCis.Interactive.DemoController.ExtraViewsNeedIdle);
      try
      {
        ExtraViews views = s.ComputeViews(cancel);
        return TypedResults.Ok(new ViewsJson(views.Width, views.Height, views.AllRaysKnown, Enum.GetNames<MapKind>()));
      }
      catch (InvalidOperationException e)
      {
        return Problems.Conflict(e.Message);
      }
    });
    api.MapGet("/views/{kind}.png", Results<FileContentHttpResult, ProblemHttpResult> (string kind, StudioSession s) =>
      TryView(s, kind, out ExtraViews? v, out MapKind k, out ProblemHttpResult? problem)
        ? TypedResults.File(PngEncoder.Default.Encode(Rgb8Image.FromFloatImage(v.ToImage(k), 1.0)), "image/png")
        : problem);
    api.MapGet("/views/{kind}.csv", Results<FileContentHttpResult, ProblemHttpResult> (string kind, StudioSession s) =>
      TryView(s, kind, out ExtraViews? v, out MapKind k, out ProblemHttpResult? problem)
        ? TypedResults.File(Text(w => v.WriteCsv(k, w)), "text/csv", $"{kind.ToLowerInvariant()}.csv")
        : problem);
    api.MapGet("/views/points.ply", Results<FileContentHttpResult, ProblemHttpResult> (StudioSession s) =>
      s.Views is ExtraViews v
        ? TypedResults.File(Text(w => v.WritePointCloud(w, s.FinalImage(), s.Controller.LastResult?.Gamma ?? 1.0)), "application/octet-stream", "points.ply")
        : Problems.NotFound("compute the extra views first"));
    api.MapGet("/views/value", Results<Ok<ValueJson>, ProblemHttpResult> (string kind, int x, int y, StudioSession s) =>
      !TryView(s, kind, out ExtraViews? v, out MapKind k, out ProblemHttpResult? problem) ? problem
      : x < 0 || y < 0 || x >= v.Width || y >= v.Height ? Problems.BadRequest($"pixel [{x}, {y}] lies outside the {v.Width}x{v.Height} image")
      : TypedResults.Ok(new ValueJson(v.Describe(k, x, y))));
  }

  /// <summary>The computed views and the view named <paramref name="kind"/>, or a 404 saying what is missing.</summary>
  static bool TryView(StudioSession s, string kind, [NotNullWhen(true)] out ExtraViews? views, out MapKind k, [NotNullWhen(false)] out ProblemHttpResult? problem)
  {
    views = s.Views;
    k = default;
    problem = null;
    if (views == null)
      problem = Problems.NotFound("compute the extra views first");
    else if (!Enum.TryParse(kind, ignoreCase: true, out k) || !Enum.IsDefined(k))
      problem = Problems.NotFound($"no view '{kind}'; the views are {string.Join(", ", Enum.GetNames<MapKind>())}");
    else
      return true;
    return false;
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
