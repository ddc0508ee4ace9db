using System;
using System.IO;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;
using Rendering;

namespace GrCis.Studio;

/// <summary>Animation: render a time range's frames (into a folder given on the command line, if asked), follow them, scrub through them.</summary>
internal static class AnimationApi
{
  /// <summary>What the page sends: the scene, its parameters and settings, the range, optionally a folder for the frames, and the algorithm (as to render).</summary>
  /// <remarks>A null start, end or fps is the script's own (else the scene's range, else 0 to 10 s at 25 fps); <c>given</c> as to render.</remarks>
  internal sealed record AnimationBody(string Scene, string? Param, RenderSettings? Settings, double? Start, double? End, double? Fps, string? Folder,
                                       string? Algorithm = null, string[]? Given = null);

  public static void MapAnimationApi(this IEndpointRouteBuilder api)
  {
    api.MapPost("/animation", Start);
    api.MapGet("/animation", Results<Ok<AnimationStatus>, NotFound> (StudioSession s) =>
      s.Animation is { } a ? TypedResults.Ok(a.Status()) : TypedResults.NotFound());
    api.MapPost("/animation/stop", (StudioSession s) =>
    {
      s.Animation?.Stop();
      return TypedResults.NoContent();
    });
    api.MapGet("/animation/frame/{k:int}.png", Results<FileContentHttpResult, NotFound> (int k, StudioSession s) =>
      s.Animation?.Frame(k) is byte[] png ? TypedResults.File(png, "image/png") : TypedResults.NotFound());
    api.MapGet("/animation/frame/{k:int}.glb", Results<FileContentHttpResult, NotFound> (int k, StudioSession s) =>
      StudioSceneFiles.FrameGlb(s, k) is byte[] glb ? TypedResults.File(glb, "model/gltf-binary", $"frame{k:0000}.glb") : TypedResults.NotFound());
  }

  static async Task<Results<Accepted, ProblemHttpResult>> Start(AnimationBody body, StudioSession s, AllowedFiles files, HttpRequest request)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(body.Scene ?? "");
    if (entry == null)
      return Problems.NotFound($"no scene '{body.Scene}'");
    if (body.Start > body.End || body.Fps <= 0.0)
      return Problems.BadRequest("the range needs start ≤ end and fps > 0");
    if (!StudioApi.TryAlgorithm(body.Algorithm, out RenderAlgorithm? algorithm, out ProblemHttpResult? bad))
      return bad;
    if (!StudioApi.TryGiven(body.Given, out GivenSettings given, out bad))
      return bad;
    if (entry.Path != null && !files.Allows(entry.Path))
      return Problems.Outside(Path.GetFileName(entry.Path));
    string? folder = null;
    if (!string.IsNullOrWhiteSpace(body.Folder))
    {
      // A folder for frames must lie inside a folder given on the command line, really (links followed); the frames
      // are written into that real folder.
      if (files.Resolve(Path.Combine(Path.GetFullPath(body.Folder), "out0000.png")) is not string first)
        return Problems.Outside($"folder '{body.Folder}'");
      folder = Path.GetDirectoryName(first);
    }
    RenderSettings settings;
    try
    {
      settings = (body.Settings ?? s.Controller.Settings).Validate();
    }
    catch (InvalidSettingException e)
    {
      return Problems.BadRequest(e.Message);
    }
    // Busy as the status shows it; a render that has ended, or was stopped, is let finish first (its last image kept).
    const string running = "a render or an animation is running; stop it first";
    if (s.Animation is { Running: true })
      return Problems.Conflict(running);
    if (!await s.Controller.SettleAsync())
      return Problems.NotSettled(s.Controller, running);
    // Another request may have started one while this one waited.
    if (s.Animation is { Running: true })
      return Problems.Conflict(running);
    entry.ParameterText = body.Param ?? entry.ParameterText;
    s.Controller.Selected = entry;
    s.Controller.Settings = settings;
    s.Controller.Algorithm = algorithm;
    s.Controller.Given = given;
    AnimationRun run;
    try
    {
      run = s.Controller.CreateAnimation(body.Start, body.End, body.Fps);
    }
    catch (Exception e) when (e is SceneEvaluationException or ArgumentException)
    {
      // A range from the script or the user that cannot be: its first sentence, without the parameter's name.
      string message = e is ArgumentException a && a.ParamName != null ? e.Message.Split(" (Parameter")[0] : e.Message;
      return Problems.BadRequest(message);
    }
    AnimationTimeline t = run.Timeline;
    if (t.FrameCount > 100_000)
      return Problems.BadRequest($"the range {t.Start}–{t.End} s at {t.Fps} fps has {t.FrameCount} frames; at most 100000");
    s.ActedFor(request);
    s.Animation = StudioAnimation.Start(run, folder, s.Changed);
    return TypedResults.Accepted((string?)null);
  }
}
