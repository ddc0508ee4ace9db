using System.Collections.Generic;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;

namespace GrCis.Studio;

/// <summary>
/// The studio's errors as RFC 7807 problem details (<c>application/problem+json</c>): the status's title, and in
/// <c>detail</c> the sentence the page shows.
/// </summary>
internal static class Problems
{
  public static ProblemHttpResult BadRequest(string detail, IDictionary<string, object?>? extensions = null) =>
    TypedResults.Problem(detail, statusCode: StatusCodes.Status400BadRequest, extensions: extensions);

  public static ProblemHttpResult NotFound(string detail) => TypedResults.Problem(detail, statusCode: StatusCodes.Status404NotFound);

  public static ProblemHttpResult Conflict(string detail) => TypedResults.Problem(detail, statusCode: StatusCodes.Status409Conflict);

  public static ProblemHttpResult PreconditionFailed(string detail) => TypedResults.Problem(detail, statusCode: StatusCodes.Status412PreconditionFailed);

  /// <summary>
  /// What an action that needs the render to be over answers when <see cref="GrCis.Interactive.DemoController.SettleAsync"/>
  /// refused: <paramref name="busy"/> while the render is busy as the status shows it, else that a stopped render (a
  /// script that ignores the stop) has not ended yet.
  /// </summary>
  public static ProblemHttpResult NotSettled(GrCis.Interactive.DemoController controller, string busy) =>
    Conflict(controller.IsBusy ? busy : "the stopped render is still ending (its script ignores the stop); try again in a moment");

  /// <summary>A path that lies outside the folders given on the command line (links followed), or a scene whose file does.</summary>
  public static ProblemHttpResult Outside(string what) =>
    TypedResults.Problem($"{what} lies outside the scripts and folders given to grcis studio", statusCode: StatusCodes.Status403Forbidden);
}
