using System;
using System.Linq;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;

namespace GrCis.Studio;

/// <summary>The page's file picker: the scripts inside the given folders (subfolders too), and adding one to the scene list.</summary>
internal static class FilesApi
{
  internal sealed record AddBody(string Path);

  public static void Map(WebApplication app)
  {
    app.MapGet("/api/files", (AllowedFiles files) => files.Scripts());
    app.MapPost("/api/scenes/add", (AddBody body, StudioSession s, AllowedFiles files) =>
    {
      if (string.IsNullOrWhiteSpace(body.Path) || !files.Allows(body.Path))
        return Results.StatusCode(StatusCodes.Status403Forbidden);
      if (!body.Path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || !System.IO.File.Exists(files.Resolve(body.Path)))
        return Results.NotFound(new { error = $"{body.Path}: no such scene script" });
      SceneEntry entry;
      lock (s.Controller.Catalog)
        entry = s.Controller.Catalog.AddScriptFile(body.Path);
      return Results.Ok(new { name = entry.Name });
    });
  }
}
