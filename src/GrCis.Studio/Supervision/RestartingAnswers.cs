using System;
using System.Text.Json;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Http;

namespace GrCis.Studio;

/// <summary>
/// What the supervisor answers the page itself while the studio process restarts: <c>/api/status</c> says nothing
/// runs and why it restarts; the event stream sends that status once and ends when the new process answers.
/// </summary>
internal static class RestartingAnswers
{
  /// <summary>The status while the studio process restarts.</summary>
  public static StudioStatus Status(string why) =>
    new(false, 0, 0, 0, "", why, [], []) { Phase = "restarting", Generation = -1 };

  /// <summary>Answers <c>/api/status</c> or <c>/api/events</c> (<paramref name="context"/>'s path) until <paramref name="answering"/>, the new process, answers.</summary>
  public static Task AnswerAsync(HttpContext context, string why, Task answering, JsonSerializerOptions json) =>
    context.Request.Path == "/api/events"
      ? EventsAsync(context, why, answering, json)
      : context.Response.WriteAsJsonAsync(Status(why), json, context.RequestAborted);

  // One status event, then the end of the stream once the new studio process answers: the browser reconnects by
  // itself (after the half second asked for) and so reaches the new one.
  static async Task EventsAsync(HttpContext context, string why, Task answering, JsonSerializerOptions json)
  {
    context.Response.ContentType = "text/event-stream";
    context.Response.Headers.CacheControl = "no-cache";
    string data = JsonSerializer.Serialize(Status(why), json);
    try
    {
      await context.Response.WriteAsync($"retry: 500\nevent: status\ndata: {data}\n\n", context.RequestAborted).ConfigureAwait(false);
      await context.Response.Body.FlushAsync(context.RequestAborted).ConfigureAwait(false);
      await answering.WaitAsync(TimeSpan.FromSeconds(15), context.RequestAborted).ConfigureAwait(false);
    }
    catch (Exception e) when (e is OperationCanceledException or TimeoutException)
    {
      // The page went, or the restart takes long: the browser asks again.
    }
  }
}
