using System.Net.Http;
using System.Threading;
using System.Threading.Tasks;
using Microsoft.AspNetCore.Http;
using Yarp.ReverseProxy.Forwarder;

namespace GrCis.Studio;

/// <summary>
/// Forwards a request as YARP does by default (every header, the body streamed) but with the Host the user sent, not the
/// studio process's own address: that process checks Host and Origin against the address the user reached
/// (<see cref="StudioOptions.PublicPort"/>), so its access rules hold behind the supervisor as they do without one.
/// </summary>
internal sealed class UserHostTransformer : HttpTransformer
{
  public static readonly UserHostTransformer Instance = new();

  public override async ValueTask TransformRequestAsync(HttpContext httpContext, HttpRequestMessage proxyRequest, string destinationPrefix,
                                                        CancellationToken cancellationToken)
  {
    await base.TransformRequestAsync(httpContext, proxyRequest, destinationPrefix, cancellationToken).ConfigureAwait(false);
    proxyRequest.Headers.Host = httpContext.Request.Host.Value;
  }
}
