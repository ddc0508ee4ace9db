using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;

namespace GrCis.Studio;

/// <summary>What the studio's supervisor asks the studio process it runs (<see cref="StudioSupervisor"/>).</summary>
internal static class SupervisionApi
{
  /// <summary><c>stoppedWorkRunning</c>: what the last Stop stopped still runs (<see cref="GrCis.Interactive.DemoController.StoppedWorkRunning"/>).</summary>
  internal sealed record WorkJson(bool StoppedWorkRunning);

  public static void MapSupervisionApi(this IEndpointRouteBuilder api) =>
    api.MapGet("/supervision", (StudioSession s) => TypedResults.Ok(new WorkJson(s.Controller.StoppedWorkRunning)));
}
