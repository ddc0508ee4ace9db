using System.Collections.Generic;
using System.Linq;
using System.Threading.Tasks;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;

namespace GrCis.Studio;

/// <summary>The last renders (GrCis kept five): list them, go back and forward; the image on show follows.</summary>
internal static class HistoryApi
{
  /// <summary>The kept renders (oldest first) and which is on show.</summary>
  internal sealed record HistoryJson(int Position, bool CanGoBack, bool CanGoForward, IReadOnlyList<HistoryItem> Items);

  internal sealed record HistoryItem(string Label, bool Complete);

  public static void MapHistoryApi(this IEndpointRouteBuilder api)
  {
    api.MapGet("/history", (StudioSession s) => TypedResults.Ok(List(s.Controller.History)));
    api.MapPost("/history/back", (StudioSession s) => Move(s, back: true));
    api.MapPost("/history/forward", (StudioSession s) => Move(s, back: false));
    // Any kept render's image (0 = the oldest), for the page's A/B comparison with the image on show.
    api.MapGet("/history/{i:int}.png", Results<FileContentHttpResult, NotFound> (int i, StudioSession s) =>
      s.Controller.History.Items.ElementAtOrDefault(i) is RenderRecord r
        ? TypedResults.File(Rendering.Imaging.PngEncoder.Default.Encode(r.ToRgb8()), "image/png")
        : TypedResults.NotFound());
  }

  static HistoryJson List(RenderHistory h) =>
    new(h.Position, h.CanGoBack, h.CanGoForward, h.Items.Select(r => new HistoryItem(r.ToString(), r.Complete)).ToArray());

  static async Task<Results<Ok<HistoryJson>, ProblemHttpResult>> Move(StudioSession s, bool back)
  {
    // Busy as the status shows it; a render that has ended, or was stopped, is let finish first (it adds its image here).
    if (!await s.Controller.SettleAsync())
      return Problems.NotSettled(s.Controller, "wait for the render to finish (or stop it)");
    RenderHistory h = s.Controller.History;
    RenderRecord? record = back ? h.Back() : h.Forward();
    if (record == null)
      return Problems.Conflict(back ? "no older render" : "no newer render");
    s.ShowRecord(record);
    return TypedResults.Ok(List(h));
  }
}
