using System.Linq;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;

namespace GrCis.Studio;

/// <summary>The last renders (GrCis kept five): list them, go back and forward; the image on show follows.</summary>
internal static class HistoryApi
{
  public static void Map(WebApplication app)
  {
    app.MapGet("/api/history", (StudioSession s) => List(s.Controller.History));
    app.MapPost("/api/history/back", (StudioSession s) => Move(s, back: true));
    app.MapPost("/api/history/forward", (StudioSession s) => Move(s, back: false));
    // Any kept render's image (0 = the oldest), for the page's A/B comparison with the image on show.
    app.MapGet("/api/history/{i:int}.png", (int i, StudioSession s) =>
      s.Controller.History.Items.ElementAtOrDefault(i) is RenderRecord r
        ? Results.Bytes(Rendering.Imaging.PngEncoder.Default.Encode(r.ToRgb8()), "image/png")
        : Results.NotFound());
  }

  static object List(RenderHistory h) => new
  {
    position = h.Position,
    canGoBack = h.CanGoBack,
    canGoForward = h.CanGoForward,
    items = h.Items.Select(r => new { label = r.ToString(), complete = r.Complete }),
  };

  static IResult Move(StudioSession s, bool back)
  {
    if (s.Controller.IsRendering)
      return Results.Conflict(new { error = "wait for the render to finish (or stop it)" });
    RenderHistory h = s.Controller.History;
    RenderRecord? record = back ? h.Back() : h.Forward();
    if (record == null)
      return Results.Conflict(new { error = back ? "no older render" : "no newer render" });
    s.ShowRecord(record);
    return Results.Ok(List(h));
  }
}
