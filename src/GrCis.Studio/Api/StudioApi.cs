using System;
using System.Collections.Generic;
using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;
using Microsoft.Extensions.Hosting;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// The studio's endpoints under <c>/api</c>: the scene list, render/stop/status and the event stream, the image (PNG as
/// <c>grcis render</c> writes it, PFM linear), the pixel probe and the scripts' text; the other groups of endpoints
/// (views, history, animation, files) map themselves into the same group. Errors are problem details (<see cref="Problems"/>).
/// </summary>
internal static class StudioApi
{
  /// <summary>What <c>POST /api/render</c> answers: the number of the render started, which its events carry.</summary>
  internal sealed record RenderStarted(long RenderId);

  public static RouteGroupBuilder MapStudioApi(this IEndpointRouteBuilder app)
  {
    RouteGroupBuilder api = app.MapGroup("/api");
    api.MapGet("/scenes", Scenes);
    api.MapGet("/scene/boxes", Boxes);
    api.MapGet("/settings", (StudioSession s) => TypedResults.Ok(s.Controller.Settings));
    api.MapPost("/render", Render);
    api.MapPost("/scene/values", ScriptValues);
    api.MapPost("/stop", (StudioSession s) =>
    {
      // Whatever runs: the script being built, the render, a saved script being compiled, and an animation.
      s.Stop();
      s.Animation?.Stop();
      return TypedResults.NoContent();
    });
    api.MapGet("/status", (StudioSession s) => TypedResults.Ok(s.Status()));
    // The state pushed as it changes (StudioEvents); the stream ends when the page goes or the studio stops.
    api.MapGet("/events", (StudioSession s, IHostApplicationLifetime life, CancellationToken aborted) =>
      TypedResults.ServerSentEvents(StudioEvents.Stream(s, life.ApplicationStopping, aborted)));
    api.MapGet("/image.png", Image);
    api.MapGet("/image.pfm", Results<FileContentHttpResult, NotFound> (StudioSession s) =>
      s.FinalImage() is FloatImage f ? TypedResults.File(PfmWriter.Encode(f), "application/octet-stream", "render.pfm") : TypedResults.NotFound());
    // The scene on show for Blender or any 3D viewer: what grcis export writes (docs/export.md).
    api.MapGet("/scene.glb", Results<FileContentHttpResult, ProblemHttpResult> (StudioSession s) =>
      StudioSceneFiles.StillGlb(s) is byte[] glb ? TypedResults.File(glb, "model/gltf-binary", "scene.glb") : Problems.NotFound("render something first"));
    // The same scene for the page's 3D view, and the points its rays hit (Scene3dApi).
    api.MapScene3dApi();
    api.MapGet("/probe", Probe);
    api.MapGet("/source", Source);
    api.MapPut("/source", SaveSource);
    api.MapGet("/file", Results<ContentHttpResult, NotFound, ProblemHttpResult> (string path, AllowedFiles files) =>
      files.Resolve(path) is not string real ? Problems.Outside(path)
      : File.Exists(real) ? TypedResults.Text(File.ReadAllText(real), "text/plain; charset=utf-8")
      : TypedResults.NotFound());
    api.MapViewsApi();
    api.MapHistoryApi();
    api.MapAnimationApi();
    api.MapEditorApi();
    api.MapFilesApi();
    api.MapSupervisionApi();
    return api;
  }

  static Ok<SceneList> Scenes(StudioSession s)
  {
    // The file picker may add an entry meanwhile (FilesApi): list a copy.
    SceneEntry[] entries;
    lock (s.Controller.Catalog)
      entries = s.Controller.Catalog.Entries.ToArray();
    return TypedResults.Ok(new SceneList(s.Controller.Selected?.Name,
      entries.Select(e => new SceneItem(e.Name, e.Label, e.Kind.ToString(), e.Tooltip, e.ParameterText, e.Path == null ? null : Path.GetFileName(e.Path))).ToArray()));
  }

  internal sealed record SceneList(string? Selected, IReadOnlyList<SceneItem> Scenes);

  /// <summary>
  /// A scene of the list: its name (the key of every request), the label the list shows (a script's file name), its kind
  /// (built-in, script), its parameter text and tooltip, its script file's name (null for a built-in).
  /// </summary>
  internal sealed record SceneItem(string Name, string Label, string Kind, string? Tooltip, string? Param, string? File);

  internal sealed record BoxJson(double[] Min, double[] Max);

  static Results<Ok<BoxJson[]>, ProblemHttpResult> Boxes(StudioSession s) =>
    s.SceneBoxes() is { } boxes
      ? TypedResults.Ok(boxes.Select(b => new BoxJson([b.Min.X, b.Min.Y, b.Min.Z], [b.Max.X, b.Max.Y, b.Max.Z])).ToArray())
      : Problems.NotFound("render something first");

  static Results<FileContentHttpResult, NotFound> Image(StudioSession s, HttpResponse response)
  {
    if (s.DisplayImage() is not var (image, version))
      return TypedResults.NotFound();
    response.Headers["X-Image-Version"] = version.ToString(System.Globalization.CultureInfo.InvariantCulture);
    response.Headers.CacheControl = "no-store";
    return TypedResults.File(PngEncoder.Default.Encode(image), "image/png");
  }

  static Results<FileContentHttpResult, StatusCodeHttpResult, ProblemHttpResult> Source(string scene, StudioSession s, AllowedFiles files,
                                                                                        HttpRequest request, HttpResponse response)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(scene);
    if (entry?.Path == null)
      return Problems.NotFound($"'{scene}' is not a script file");
    if (files.Resolve(entry.Path) is not string real)
      return Problems.Outside(Path.GetFileName(entry.Path));
    // The editor asks with the tag of the text it holds: 304 while the file is unchanged, else the new text.
    byte[] bytes = File.ReadAllBytes(real);
    string tag = SourceTag(bytes);
    response.Headers.ETag = tag;
    response.Headers.CacheControl = "no-store";
    if (request.Headers.IfNoneMatch == tag)
      return TypedResults.StatusCode(StatusCodes.Status304NotModified);
    return TypedResults.File(bytes, "text/plain; charset=utf-8");
  }

  /// <summary>What <c>PUT /api/source</c> answers for a script that is compiled, not rendered: the check's number, which its <c>checked</c> event carries.</summary>
  internal sealed record CheckStarted(long Check);

  static async Task<Results<NoContent, Accepted<CheckStarted>, ProblemHttpResult>> SaveSource(string scene, HttpRequest request, HttpResponse response,
                                                                                StudioSession s, AllowedFiles files)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(scene);
    if (entry?.Path == null)
      return Problems.NotFound($"'{scene}' is not a script file");
    // The real file is written (a link inside the folders keeps pointing at it); a link leading out is refused.
    if (files.Resolve(entry.Path) is not string real)
      return Problems.Outside(Path.GetFileName(entry.Path));
    // The editor says which text it started from (If-Match: its tag): a file changed on disk since is not overwritten.
    string? expected = request.Headers.IfMatch;
    if (!string.IsNullOrEmpty(expected) && File.Exists(real) && expected != SourceTag(File.ReadAllBytes(real)))
      return Problems.PreconditionFailed($"{Path.GetFileName(entry.Path)} changed on disk since the editor loaded it: reload it, or save again to replace it");
    using var reader = new StreamReader(request.Body, System.Text.Encoding.UTF8);
    string text = await reader.ReadToEndAsync();
    if (!SaveAtomically(real, text, files))
      return Problems.Outside(Path.GetFileName(entry.Path));
    s.ActedFor(request);
    response.Headers.ETag = SourceTag(File.ReadAllBytes(real));
    // The selected script's watcher re-renders it (as for a save from any other editor): 204. Any other script is
    // compiled here, so its diagnostics show too: 202, and the phase is compiling until they are known.
    if (IsWatched(s.Controller, entry))
      return TypedResults.NoContent();
    return TypedResults.Accepted((string?)null, new CheckStarted(s.Check(entry)));
  }

  /// <summary>
  /// What the page sends to render: the scene's name, its parameter text, the settings, the algorithm
  /// (<c>grcis render --algorithm</c>'s names; null or empty = the scene's choice), and whether to render in passes
  /// of samples (true), by tiles (false) or as suits the algorithm (null).
  /// </summary>
  /// <remarks>
  /// <c>given</c> names the settings the user changed (<see cref="GivenSettings"/>: <c>Size</c>, <c>SamplesPerPixel</c>,
  /// <c>Jitter</c>, <c>Shadows</c>, <c>Reflections</c>, <c>Refractions</c>, <c>Gamma</c>): they win over the script's own
  /// values, as options typed on the command line do; the others are the script's where it sets them. Absent = none.
  /// </remarks>
  internal sealed record RenderBody(string Scene, string? Param, RenderSettings? Settings, string? Algorithm = null, bool? Progressive = null,
                                    string[]? Given = null);

  /// <summary>A scene and its parameter text, to read the script's own values.</summary>
  internal sealed record SceneBody(string Scene, string? Param);

  /// <summary>The request's <c>given</c> names as flags, or a 400 naming the one that is not known.</summary>
  internal static bool TryGiven(string[]? names, out GivenSettings given, [NotNullWhen(false)] out ProblemHttpResult? bad)
  {
    given = GivenSettings.None;
    bad = null;
    foreach (string name in names ?? [])
    {
      if (!Enum.TryParse(name, ignoreCase: true, out GivenSettings flag) || !Enum.IsDefined(flag) || flag == GivenSettings.Algorithm)
      {
        bad = Problems.BadRequest($"given setting '{name}' is not known; use Size, SamplesPerPixel, Jitter, Shadows, Reflections, Refractions or Gamma");
        return false;
      }
      given |= flag;
    }
    return true;
  }

  /// <summary>The script's own values for the fields; null where it sets none.</summary>
  internal sealed record ScriptValuesJson(int? Width, int? Height, int? SamplesPerPixel, string? Algorithm, double? Start, double? End, double? Fps,
                                          string? Tooltip);

  /// <summary>
  /// The script's own values for the fields (size, samples per pixel, algorithm, animation range; null where it sets
  /// none) and its tooltip: the scene is built, not rendered. A script that does not build is a 400 whose problem details
  /// carry its compiler diagnostics (<c>diagnostics</c>, as in the status).
  /// </summary>
  static async Task<Results<Ok<ScriptValuesJson>, ProblemHttpResult>> ScriptValues(SceneBody body, StudioSession s, AllowedFiles files)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(body.Scene ?? "");
    if (entry == null)
      return Problems.NotFound($"no scene '{body.Scene}'");
    if (entry.Path != null && !files.Allows(entry.Path))
      return Problems.Outside(Path.GetFileName(entry.Path));
    if (body.Param != null)
      entry.ParameterText = body.Param;
    SceneOverrides values;
    try
    {
      values = await s.Controller.ReadScriptValuesAsync(entry);
    }
    catch (SceneEvaluationException e)
    {
      return Problems.BadRequest(e.Message, new Dictionary<string, object?> { ["diagnostics"] = ScriptErrors.In(DemoErrorEventArgs.DiagnosticsOf(e), entry.Path) });
    }
    catch (OperationCanceledException)
    {
      return Problems.Conflict("stopped");
    }
    return TypedResults.Ok(new ScriptValuesJson(values.Width, values.Height, values.Supersampling, values.Algorithm, values.Start, values.End,
                                                values.Fps, entry.Tooltip));
  }

  static Results<Accepted<RenderStarted>, ProblemHttpResult> Render(RenderBody body, StudioSession s, AllowedFiles files, HttpRequest request)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(body.Scene ?? "");
    if (entry == null)
      return Problems.NotFound($"no scene '{body.Scene}'");
    if (entry.Path != null && !files.Allows(entry.Path))
      return Problems.Outside(Path.GetFileName(entry.Path));
    if (!TryAlgorithm(body.Algorithm, out RenderAlgorithm? algorithm, out ProblemHttpResult? bad))
      return bad;
    if (!TryGiven(body.Given, out GivenSettings given, out bad))
      return bad;
    RenderSettings settings = body.Settings ?? s.Controller.Settings;
    try
    {
      settings = settings.Validate();
    }
    catch (InvalidSettingException e)
    {
      return Problems.BadRequest(e.Message);
    }
    s.ActedFor(request);
    long id = s.Render(entry, body.Param ?? entry.ParameterText, settings, algorithm, body.Progressive, given);
    return TypedResults.Accepted((string?)null, new RenderStarted(id));
  }

  /// <summary>The request's <c>algorithm</c> field: null or empty = the scene's choice, else one of the CLI's names, else a 400.</summary>
  internal static bool TryAlgorithm(string? name, out RenderAlgorithm? algorithm, [NotNullWhen(false)] out ProblemHttpResult? bad)
  {
    algorithm = null;
    bad = null;
    if (string.IsNullOrEmpty(name))
      return true;
    if (RenderAlgorithmNames.TryParse(name, out RenderAlgorithm a))
    {
      algorithm = a;
      return true;
    }
    bad = Problems.BadRequest($"algorithm '{name}' is not known; use {string.Join(", ", RenderAlgorithmNames.All)}, or leave it out for the scene's choice");
    return false;
  }

  /// <summary>
  /// One pixel's read-out: its colour, the first sample's, the pixel's hash and its ray tree, and the part of the 3D view
  /// its primary ray hit (its index in <c>/scene/tessellation</c>'s parts and its name, e.g. <c>Sphere 2</c>; null for the
  /// background or a solid the view does not show).
  /// </summary>
  internal sealed record ProbeJson(int X, int Y, double[] Pixel, double[] Sample, long Hash, RayJson? Rays, int? Part, string? PartName);

  /// <summary>
  /// One ray of the tree: where it starts and goes, what it hit (the solid's class, the normal there, the index of the 3D
  /// view's part), and the rays it spawned.
  /// </summary>
  internal sealed record RayJson(string Kind, int Depth, double[] Origin, double[] Direction, double[]? Hit, double[]? Normal, string? Solid, int? Part,
                                 bool Blocked, RayJson[] Children);

  static Results<Ok<ProbeJson>, ProblemHttpResult> Probe(StudioSession s, int x, int y)
  {
    ProbeResult probe;
    RenderJob? job = s.Controller.LastJob;
    try
    {
      probe = s.Controller.Probe(x, y);
    }
    catch (Exception e) when (e is InvalidOperationException or ArgumentOutOfRangeException)
    {
      return Problems.BadRequest(e.Message);
    }
    // The parts of the scene probed (a render started meanwhile has other nodes: none named then).
    SceneParts? parts = job != null && ReferenceEquals(job, s.Controller.LastJob) ? s.StillScene.For(job).Parts : null;
    int? part = probe.Rays is { Kind: Rendering.Observation.RayKind.Primary } primary ? parts?.IndexOf(primary.Solid) : null;
    return TypedResults.Ok(new ProbeJson(probe.X, probe.Y, probe.PixelColor, probe.SampleColor, probe.Hash, probe.Rays == null ? null : Ray(probe.Rays, parts),
                                         part, part is int i ? parts!.NameOf(i) : null));
  }

  static RayJson Ray(RayNode n, SceneParts? parts) => new(
    n.Kind.ToString(), n.Depth, [n.Origin.X, n.Origin.Y, n.Origin.Z], [n.Direction.X, n.Direction.Y, n.Direction.Z],
    n.Hit is { } h ? [h.X, h.Y, h.Z] : null, n.Normal is { } m ? [m.X, m.Y, m.Z] : null, n.Solid?.GetType().Name, parts?.IndexOf(n.Solid), n.Blocked,
    n.Children.Select(c => Ray(c, parts)).ToArray());

  /// <summary>Whether the controller's watcher follows <paramref name="entry"/>'s file (the selected script's).</summary>
  static bool IsWatched(DemoController controller, SceneEntry entry) =>
    controller.WatchScript && controller.Selected?.Path is string watched && entry.Path != null &&
    string.Equals(Path.GetFullPath(watched), Path.GetFullPath(entry.Path), StringComparison.Ordinal);

  /// <summary>A script's version as an entity tag: the start of its SHA-256, quoted.</summary>
  internal static string SourceTag(byte[] bytes) => "\"" + Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(bytes), 0, 16) + "\"";

  /// <summary>
  /// Writes the whole text to a new temporary file beside <paramref name="real"/>, then renames it over: never half a
  /// script. The temporary file has a random name and is created new (<see cref="FileMode.CreateNew"/> fails on any
  /// existing name, a link included), so nothing planted beside the script is written through. Before the rename the
  /// temporary file and the target are resolved again: when either now leads out of the allowed folders (a link planted
  /// meanwhile), nothing is renamed and false is returned. A rename replaces a link, never writes through it.
  /// </summary>
  static bool SaveAtomically(string real, string text, AllowedFiles files)
  {
    string dir = Path.GetDirectoryName(real)!;
    string temp = Path.Combine(dir, "." + Path.GetFileName(real) + ".grcis-save-" + Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(8)));
    try
    {
      using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
      using (var writer = new StreamWriter(stream, new UTF8Encoding(encoderShouldEmitUTF8Identifier: false)))
        writer.Write(text);
      if (!string.Equals(files.Resolve(temp), temp, StringComparison.Ordinal) || files.Resolve(real) == null)
      {
        File.Delete(temp);
        return false;
      }
      File.Move(temp, real, overwrite: true);
      return true;
    }
    catch
    {
      try
      {
        File.Delete(temp);
      }
      catch (Exception e) when (e is IOException or UnauthorizedAccessException)
      {
        // The save's own failure is the one to report.
      }
      throw;
    }
  }
}
