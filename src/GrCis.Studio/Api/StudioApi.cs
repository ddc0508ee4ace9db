using System;
using System.Diagnostics.CodeAnalysis;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Threading.Tasks;
using GrCis.Hosting;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Rendering.Imaging;

namespace GrCis.Studio;

/// <summary>
/// The studio's endpoints: the page (from the assembly), the scene list, render/stop/status, the image
/// (PNG as <c>grcis render</c> writes it, PFM linear), the pixel probe and the scripts' text.
/// </summary>
internal static class StudioApi
{
  public static void Map(WebApplication app)
  {
    app.MapGet("/", () => Page("index.html", "text/html; charset=utf-8"));
    app.MapGet("/{file}", (string file) => Page(file, ContentType(file)));
    app.MapGet("/vendor/{file}", (string file) => Page("vendor/" + file, ContentType(file)));
    app.MapGet("/api/scene/boxes", (StudioSession s) =>
      s.Controller.LastJob is { } job
        ? Results.Ok(Rendering.Accel.PreparedScene.Prepare(job.Scene.Intersectable).WorldBoxes()
            .Select(b => new { min = new[] { b.Min.X, b.Min.Y, b.Min.Z }, max = new[] { b.Max.X, b.Max.Y, b.Max.Z } }))
        : Results.NotFound(new { error = "render something first" }));

    app.MapGet("/api/scenes", (StudioSession s) =>
    {
      // The file picker may add an entry meanwhile (FilesApi): list a copy.
      SceneEntry[] entries;
      lock (s.Controller.Catalog)
        entries = s.Controller.Catalog.Entries.ToArray();
      return new
      {
        selected = s.Controller.Selected?.Name,
        scenes = entries.Select(e => new
        {
          name = e.Name,
          kind = e.Kind.ToString(),
          tooltip = e.Tooltip,
          param = e.ParameterText,
          file = e.Path == null ? null : Path.GetFileName(e.Path),
        }),
      };
    });
    app.MapGet("/api/settings", (StudioSession s) => s.Controller.Settings);
    app.MapPost("/api/render", (RenderBody body, StudioSession s, AllowedFiles files, HttpRequest request) => Render(body, s, files, request));
    app.MapPost("/api/scene/values", (SceneBody body, StudioSession s, AllowedFiles files) => ScriptValues(body, s, files));
    app.MapPost("/api/stop", (StudioSession s) =>
    {
      // Whatever runs: the script being built, the render, a saved script being compiled, and an animation.
      s.Stop();
      s.Animation?.Stop();
      return Results.NoContent();
    });
    app.MapGet("/api/status", (StudioSession s) => s.Status());
    app.MapGet("/api/image.png", (StudioSession s, HttpResponse response) =>
    {
      if (s.DisplayImage() is not var (image, version))
        return Results.NotFound();
      response.Headers["X-Image-Version"] = version.ToString(System.Globalization.CultureInfo.InvariantCulture);
      response.Headers.CacheControl = "no-store";
      return Results.Bytes(PngEncoder.Default.Encode(image), "image/png");
    });
    app.MapGet("/api/image.pfm", (StudioSession s) =>
      s.FinalImage() is FloatImage f ? Results.Bytes(PfmWriter.Encode(f), "application/octet-stream", "render.pfm") : Results.NotFound());
    app.MapGet("/api/probe", (int x, int y, StudioSession s) => Probe(s, x, y));
    app.MapGet("/api/source", (string scene, StudioSession s, AllowedFiles files, HttpRequest request, HttpResponse response) =>
    {
      SceneEntry? entry = s.Controller.Catalog.Find(scene);
      if (entry?.Path == null)
        return Results.NotFound();
      if (files.Resolve(entry.Path) is not string real)
        return Results.StatusCode(StatusCodes.Status403Forbidden);
      // The editor asks with the tag of the text it holds: 304 while the file is unchanged, else the new text.
      byte[] bytes = File.ReadAllBytes(real);
      string tag = SourceTag(bytes);
      response.Headers.ETag = tag;
      response.Headers.CacheControl = "no-store";
      if (request.Headers.IfNoneMatch == tag)
        return Results.StatusCode(StatusCodes.Status304NotModified);
      return Results.Bytes(bytes, "text/plain; charset=utf-8");
    });
    ViewsApi.Map(app);
    HistoryApi.Map(app);
    AnimationApi.Map(app);
    FilesApi.Map(app);
    app.MapPut("/api/source", async (string scene, HttpRequest request, HttpResponse response, StudioSession s, AllowedFiles files) =>
    {
      SceneEntry? entry = s.Controller.Catalog.Find(scene);
      if (entry?.Path == null)
        return Results.NotFound();
      // The real file is written (a link inside the folders keeps pointing at it); a link leading out is refused.
      if (files.Resolve(entry.Path) is not string real)
        return Results.StatusCode(StatusCodes.Status403Forbidden);
      // The editor says which text it started from (If-Match: its tag): a file changed on disk since is not overwritten.
      string? expected = request.Headers.IfMatch;
      if (!string.IsNullOrEmpty(expected) && File.Exists(real) && expected != SourceTag(File.ReadAllBytes(real)))
        return Results.Json(new { error = $"{Path.GetFileName(entry.Path)} changed on disk since the editor loaded it: reload it, or save again to replace it" },
                            statusCode: StatusCodes.Status412PreconditionFailed);
      using var reader = new StreamReader(request.Body, System.Text.Encoding.UTF8);
      string text = await reader.ReadToEndAsync();
      SaveAtomically(real, text);
      s.ActedFor(request);
      response.Headers.ETag = SourceTag(File.ReadAllBytes(real));
      // The selected script's watcher re-renders it (as for a save from any other editor): 204. Any other script is
      // compiled here, so its diagnostics show too: 202, and /api/status says compiling until they are known.
      if (IsWatched(s.Controller, entry))
        return Results.NoContent();
      s.Check(entry);
      return Results.Accepted();
    });
    app.MapGet("/api/file", (string path, AllowedFiles files) =>
      files.Resolve(path) is not string real ? Results.StatusCode(StatusCodes.Status403Forbidden)
      : File.Exists(real) ? Results.Text(File.ReadAllText(real), "text/plain; charset=utf-8")
      : Results.NotFound());
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
  internal static bool TryGiven(string[]? names, out GivenSettings given, [NotNullWhen(false)] out IResult? bad)
  {
    given = GivenSettings.None;
    bad = null;
    foreach (string name in names ?? [])
    {
      if (!Enum.TryParse(name, ignoreCase: true, out GivenSettings flag) || !Enum.IsDefined(flag) || flag == GivenSettings.Algorithm)
      {
        bad = Results.BadRequest(new { error = $"given setting '{name}' is not known; use Size, SamplesPerPixel, Jitter, Shadows, Reflections, Refractions or Gamma" });
        return false;
      }
      given |= flag;
    }
    return true;
  }

  /// <summary>
  /// The script's own values for the fields (size, samples per pixel, algorithm, animation range; null where it sets
  /// none) and its tooltip: the scene is built, not rendered.
  /// </summary>
  static async Task<IResult> ScriptValues(SceneBody body, StudioSession s, AllowedFiles files)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(body.Scene ?? "");
    if (entry == null)
      return Results.NotFound(new { error = $"no scene '{body.Scene}'" });
    if (entry.Path != null && !files.Allows(entry.Path))
      return Results.StatusCode(StatusCodes.Status403Forbidden);
    if (body.Param != null)
      entry.ParameterText = body.Param;
    SceneOverrides values;
    try
    {
      values = await s.Controller.ReadScriptValuesAsync(entry);
    }
    catch (SceneEvaluationException e)
    {
      return Results.BadRequest(new { error = e.Message, diagnostics = ScriptErrors.Parse(e.Message) });
    }
    catch (OperationCanceledException)
    {
      return Results.Conflict(new { error = "stopped" });
    }
    return Results.Ok(new
    {
      width = values.Width,
      height = values.Height,
      samplesPerPixel = values.Supersampling,
      algorithm = values.Algorithm,
      start = values.Start,
      end = values.End,
      fps = values.Fps,
      tooltip = entry.Tooltip,
    });
  }

  static IResult Render(RenderBody body, StudioSession s, AllowedFiles files, HttpRequest request)
  {
    SceneEntry? entry = s.Controller.Catalog.Find(body.Scene ?? "");
    if (entry == null)
      return Results.NotFound(new { error = $"no scene '{body.Scene}'" });
    if (entry.Path != null && !files.Allows(entry.Path))
      return Results.StatusCode(StatusCodes.Status403Forbidden);
    if (!TryAlgorithm(body.Algorithm, out RenderAlgorithm? algorithm, out IResult? bad))
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
      return Results.BadRequest(new { error = e.Message });
    }
    s.ActedFor(request);
    s.Render(entry, body.Param ?? entry.ParameterText, settings, algorithm, body.Progressive, given);
    return Results.Accepted();
  }

  /// <summary>The request's <c>algorithm</c> field: null or empty = the scene's choice, else one of the CLI's names, else a 400.</summary>
  internal static bool TryAlgorithm(string? name, out RenderAlgorithm? algorithm, [NotNullWhen(false)] out IResult? bad)
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
    bad = Results.BadRequest(new
    {
      error = $"algorithm '{name}' is not known; use {string.Join(", ", RenderAlgorithmNames.All)}, or leave it out for the scene's choice",
    });
    return false;
  }

  static IResult Probe(StudioSession s, int x, int y)
  {
    ProbeResult probe;
    try
    {
      probe = s.Controller.Probe(x, y);
    }
    catch (Exception e) when (e is InvalidOperationException or ArgumentOutOfRangeException)
    {
      return Results.BadRequest(new { error = e.Message });
    }
    return Results.Ok(new
    {
      x = probe.X,
      y = probe.Y,
      pixel = probe.PixelColor,
      sample = probe.SampleColor,
      hash = probe.Hash,
      rays = probe.Rays == null ? null : RayJson(probe.Rays),
    });
  }

  static object RayJson(RayNode n) => new
  {
    kind = n.Kind.ToString(),
    depth = n.Depth,
    origin = new[] { n.Origin.X, n.Origin.Y, n.Origin.Z },
    direction = new[] { n.Direction.X, n.Direction.Y, n.Direction.Z },
    hit = n.Hit is { } h ? new[] { h.X, h.Y, h.Z } : null,
    normal = n.Normal is { } m ? new[] { m.X, m.Y, m.Z } : null,
    solid = n.Solid?.GetType().Name,
    blocked = n.Blocked,
    children = n.Children.Select(RayJson).ToArray(),
  };

  /// <summary>Whether the controller's watcher follows <paramref name="entry"/>'s file (the selected script's).</summary>
  static bool IsWatched(DemoController controller, SceneEntry entry) =>
    controller.WatchScript && controller.Selected?.Path is string watched && entry.Path != null &&
    string.Equals(Path.GetFullPath(watched), Path.GetFullPath(entry.Path), StringComparison.Ordinal);

  /// <summary>A script's version as an entity tag: the start of its SHA-256, quoted.</summary>
  internal static string SourceTag(byte[] bytes) => "\"" + Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(bytes), 0, 16) + "\"";

  /// <summary>Writes the whole text to a temporary file beside <paramref name="path"/>, then moves it over: never half a script.</summary>
  static void SaveAtomically(string path, string text)
  {
    string temp = path + ".grcis-save";
    File.WriteAllText(temp, text);
    File.Move(temp, path, overwrite: true);
  }

  static string ContentType(string file) =>
    file.EndsWith(".css", StringComparison.Ordinal) ? "text/css; charset=utf-8"
    : file.EndsWith(".html", StringComparison.Ordinal) ? "text/html; charset=utf-8"
    : file.EndsWith(".txt", StringComparison.Ordinal) ? "text/plain; charset=utf-8"
    : "text/javascript; charset=utf-8";

  static IResult Page(string name, string type)
  {
    using Stream? stream = Assembly.GetExecutingAssembly().GetManifestResourceStream("page/" + name);
    if (stream == null)
      return Results.NotFound();
    using var copy = new MemoryStream();
    stream.CopyTo(copy);
    return Results.Bytes(copy.ToArray(), type);
  }
}
