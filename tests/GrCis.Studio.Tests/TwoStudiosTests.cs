using System;
using System.Collections.Generic;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>Two studios on one machine, each opened by its URL in one browser: neither locks the other out.</summary>
public sealed class TwoStudiosTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task Two_studios_on_different_ports_keep_their_own_cookies_in_one_browser()
  {
    await using StudioServer other = await StudioServer.StartAsync(new StudioOptions { Paths = [studio.ScriptsFolder] }, new List<string>());
    Assert.NotEqual(studio.Server.Port, other.Port);

    // One cookie jar for both, as a browser keeps them: per host, whatever the port.
    var jar = new CookieContainer();
    using var browser = new HttpClient(new HttpClientHandler { CookieContainer = jar, UseCookies = true });
    foreach (StudioServer s in new[] { studio.Server, other })
    {
      using HttpResponseMessage page = await browser.GetAsync(s.Url);
      Assert.Equal(HttpStatusCode.OK, page.StatusCode);
      string cookie = Assert.Single(page.Headers.GetValues("Set-Cookie"));
      Assert.StartsWith(AccessGuard.CookieNameFor(s.Port) + "=", cookie, StringComparison.Ordinal);
    }
    Assert.Equal(2, jar.GetCookies(new Uri(studio.Server.Url)).Count);

    // The first studio's page still works after the second was opened, and the second's too.
    foreach (StudioServer s in new[] { studio.Server, other })
    {
      string root = new Uri(s.Url).GetLeftPart(UriPartial.Authority);
      using HttpResponseMessage api = await browser.GetAsync(root + "/api/scenes");
      Assert.True(api.StatusCode == HttpStatusCode.OK, $"port {s.Port}: {api.StatusCode}");
    }
  }
}
