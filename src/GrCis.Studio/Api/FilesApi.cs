using System;
using GrCis.Interactive;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using Microsoft.AspNetCore.Routing;

namespace GrCis.Studio;

/// <summary>The page's file picker: the scripts inside the given folders (subfolders too), and adding one to the scene list.</summary>
internal static class FilesApi
{
  internal sealed record AddBody(string Path);

  internal sealed record Added(string Name);

  public static void MapFilesApi(this IEndpointRouteBuilder api)
  {
    api.MapGet("/files", (AllowedFiles files) => TypedResults.Ok(files.Scripts()));
    api.MapPost("/scenes/add", Results<Ok<Added>, ProblemHttpResult> (AddBody body, StudioSession s, AllowedFiles files) =>
    {
      if (string.IsNullOrWhiteSpace(body.Path) || !files.Allows(body.Path))
        return Problems.Outside($"'{body.Path}'");
      if (!body.Path.EndsWith(".cs", StringComparison.OrdinalIgnoreCase) || !System.IO.File.Exists(files.Resolve(body.Path)))
        return Problems.NotFound($"{body.Path}: no such scene script");
      SceneEntry entry;
      lock (s.Controller.Catalog)
        entry = s.Controller.Catalog.AddScriptFile(body.Path);
      return TypedResults.Ok(new Added(entry.Name));
    });
  }
}
