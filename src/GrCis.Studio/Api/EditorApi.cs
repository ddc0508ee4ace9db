using System.Collections.Generic;
using System.IO;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Editing;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;
using Microsoft.Extensions.Hosting;

namespace GrCis.Studio;

/// <summary>
/// The editor's language services under <c>/api/editor</c>: completion (and one entry's description), signature help,
/// hover, a check of unsaved text, and whether the services are loaded yet. Each request carries the editor's whole text and a character offset into it.
/// </summary>
internal static class EditorApi
{
  /// <summary>A request: the editor's text, the caret (or pointer) offset, the scene whose script it is, an entry to describe.</summary>
  internal sealed record EditorRequest(string? Text, int Position, string? Scene, string? Label);

  /// <summary>What a check answers: the compiler's errors and warnings in the script.</summary>
  internal sealed record CheckResult(IReadOnlyList<ScriptError> Diagnostics);

  public static void MapEditorApi(this RouteGroupBuilder api)
  {
    RouteGroupBuilder editor = api.MapGroup("/editor");
    editor.MapPost("/complete", async Task<Results<Ok<CompletionResult>, ProblemHttpResult>> (EditorRequest r, EditorAssistance e, CancellationToken cancel) =>
      Invalid(r) is { } problem ? problem : TypedResults.Ok(await e.Assistant.CompleteAsync(r.Text!, r.Position, cancel: cancel)));
    editor.MapPost("/describe", async Task<Results<Ok<CompletionEntry>, NoContent, ProblemHttpResult>> (EditorRequest r, EditorAssistance e, CancellationToken cancel) =>
      Invalid(r) is { } problem ? problem
      : await e.Assistant.DescribeAsync(r.Text!, r.Position, r.Label ?? "", cancel) is { } entry ? TypedResults.Ok(entry) : TypedResults.NoContent());
    editor.MapPost("/signature", async Task<Results<Ok<SignatureHelp>, NoContent, ProblemHttpResult>> (EditorRequest r, EditorAssistance e, CancellationToken cancel) =>
      Invalid(r) is { } problem ? problem
      : await e.Assistant.SignatureAsync(r.Text!, r.Position, cancel) is { } help ? TypedResults.Ok(help) : TypedResults.NoContent());
    editor.MapPost("/hover", async Task<Results<Ok<HoverInfo>, NoContent, ProblemHttpResult>> (EditorRequest r, EditorAssistance e, CancellationToken cancel) =>
      Invalid(r) is { } problem ? problem
      : await e.Assistant.HoverAsync(r.Text!, r.Position, cancel) is { } hover ? TypedResults.Ok(hover) : TypedResults.NoContent());
    editor.MapPost("/check", Check);
    // Answers once the language services are loaded: until then the page says that completion is loading. With
    // ?wait=false it answers at once: 204 when loaded, 503 with Retry-After while they load.
    editor.MapGet("/ready", async Task<Results<NoContent, ProblemHttpResult>> (EditorAssistance e, HttpResponse response, CancellationToken cancel, bool wait = true) =>
    {
      if (!wait && e.Warmed is not { IsCompletedSuccessfully: true })
      {
        _ = e.WarmAsync();
        response.Headers.RetryAfter = "1";
        return TypedResults.Problem("the editor's language services are loading", statusCode: StatusCodes.Status503ServiceUnavailable);
      }
      await e.ReadyAsync(cancel);
      return TypedResults.NoContent();
    });
  }

  static async Task<Results<Ok<CheckResult>, ProblemHttpResult>> Check(EditorRequest r, EditorAssistance e, StudioSession s, AllowedFiles files,
                                                                      CancellationToken cancel)
  {
    if (r.Text is null)
      return Problems.BadRequest("the request names no text");
    // The script's own path, so its messages and a module's data-file rules are those of a save; any scene's name will do.
    SceneEntry? entry = s.Controller.Catalog.Find(r.Scene ?? "");
    string path = entry?.Path is string p && files.Resolve(p) is string real ? real : Path.Combine(Path.GetTempPath(), "script.cs");
    return TypedResults.Ok(new CheckResult(await e.CheckAsync(r.Text, path, cancel)));
  }

  static ProblemHttpResult? Invalid(EditorRequest r) =>
    r.Text is null ? Problems.BadRequest("the request names no text")
    : r.Position < 0 || r.Position > r.Text.Length ? Problems.BadRequest($"position {r.Position} is outside the text (0 to {r.Text.Length})")
    : null;
}
