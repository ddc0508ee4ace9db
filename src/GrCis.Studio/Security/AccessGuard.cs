using System;
using System.Collections.Generic;
using System.Security.Cryptography;
using System.Text;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Mvc;
using Microsoft.Extensions.DependencyInjection;

namespace GrCis.Studio;

/// <summary>
/// Scene scripts are full-trust C#, so whoever reaches the studio can run code as its user. Every request
/// must therefore (1) name the studio itself in its Host header (no DNS rebinding), (2) come from the
/// studio's own page when it says where it comes from (Origin: no cross-site requests), and (3) carry the
/// token printed with the URL — in the query (the first page load), the <c>X-GrCis-Token</c> header or the
/// cookie the first page load sets (as Jupyter does). The cookie's name carries the port: a browser keeps cookies per
/// host, not per port, so two studios on one machine would otherwise overwrite each other's and lock each other out.
/// </summary>
public sealed class AccessGuard
{
  public const string HeaderName = "X-GrCis-Token";

  /// <summary>The name of the token's cookie for a studio on <paramref name="port"/>.</summary>
  public static string CookieNameFor(int port) => FormattableString.Invariant($"grcis-studio-token-{port}");

  readonly byte[] token;
  readonly HashSet<string> hosts;
  readonly int anyAddressPort;

  /// <param name="token">The secret every request must carry.</param>
  /// <param name="hosts">Host header values that name this studio (<c>host:port</c>, case-insensitive).</param>
  /// <param name="anyAddressPort">For a studio bound to every interface (0.0.0.0, ::): its port, under which any
  /// IP address (not a name, which DNS rebinding could point here) is accepted; else 0.</param>
  /// <param name="port">The port the studio listens on, which names its cookie (<see cref="CookieNameFor"/>).</param>
  public AccessGuard(string token, IEnumerable<string> hosts, int anyAddressPort = 0, int port = 0)
  {
    CookieName = CookieNameFor(port);
    this.token = Encoding.UTF8.GetBytes(token);
    this.hosts = new HashSet<string>(hosts, StringComparer.OrdinalIgnoreCase);
    this.anyAddressPort = anyAddressPort;
  }

  /// <summary>The cookie that carries the token for this studio's page.</summary>
  public string CookieName { get; }

  /// <summary>The Host values of a studio on <paramref name="host"/>:<paramref name="port"/>; loopback ones are reachable under each loopback name.</summary>
  public static IEnumerable<string> HostsFor(string host, int port, bool loopback)
  {
    if (loopback)
      foreach (string name in new[] { "127.0.0.1", "localhost", "[::1]" })
        yield return $"{name}:{port}";
    else
      yield return $"{StudioOptions.UrlHost(host)}:{port}";
  }

  /// <summary>Refuses a request that fails a rule (403 for Host or Origin, 401 without the token); else passes it on.</summary>
  public async Task InvokeAsync(HttpContext context, RequestDelegate next)
  {
    HttpRequest request = context.Request;
    string host = request.Host.Value ?? "";
    if (!NamesThisStudio(host))
    {
      await Refuse(context, StatusCodes.Status403Forbidden, $"the studio does not answer to host '{host}'");
      return;
    }
    string? origin = request.Headers.Origin;
    if (!string.IsNullOrEmpty(origin) && !IsOwnOrigin(origin))
    {
      await Refuse(context, StatusCodes.Status403Forbidden, "requests from other sites are refused");
      return;
    }

    string? fromQuery = request.Query["token"];
    string? header = request.Headers[HeaderName];
    string? given = fromQuery ?? (string.IsNullOrEmpty(header) ? request.Cookies[CookieName] : header);
    if (!Matches(given))
    {
      await Refuse(context, StatusCodes.Status401Unauthorized,
        "this studio needs its token: open the URL that 'grcis studio' printed (it ends in ?token=…)");
      return;
    }
    if (fromQuery != null)
      context.Response.Cookies.Append(CookieName, fromQuery, new CookieOptions
      {
        HttpOnly = true,
        SameSite = SameSiteMode.Strict,
        Path = "/",
      });
    await next(context);
  }

  bool NamesThisStudio(string host)
  {
    if (hosts.Contains(host))
      return true;
    return anyAddressPort > 0 && Uri.TryCreate("http://" + host, UriKind.Absolute, out Uri? uri) &&
           uri.Port == anyAddressPort && uri.HostNameType is UriHostNameType.IPv4 or UriHostNameType.IPv6;
  }

  bool IsOwnOrigin(string origin) =>
    Uri.TryCreate(origin, UriKind.Absolute, out Uri? uri) && uri.Scheme == Uri.UriSchemeHttp && NamesThisStudio(uri.Authority);

  bool Matches(string? given) =>
    given != null && CryptographicOperations.FixedTimeEquals(Encoding.UTF8.GetBytes(given), token);

  /// <summary>Answers with problem details (RFC 7807), as every error of the studio; the detail is the sentence for the user.</summary>
  static async Task Refuse(HttpContext context, int status, string message)
  {
    context.Response.StatusCode = status;
    var problem = new ProblemDetails { Status = status, Detail = "grcis studio: " + message };
    // The host's writer fills in the title and type as for the endpoints' problems; without one (a bare context), plain JSON.
    if (context.RequestServices?.GetService<IProblemDetailsService>() is { } writer &&
        await writer.TryWriteAsync(new ProblemDetailsContext { HttpContext = context, ProblemDetails = problem }))
      return;
    await context.Response.WriteAsJsonAsync(problem, (System.Text.Json.JsonSerializerOptions?)null, "application/problem+json");
  }

  /// <summary>A new random token (32 hex digits: 128 bits).</summary>
  public static string NewToken() => Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(16));
}
