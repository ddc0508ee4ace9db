using System;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>Each access rule of the studio: token, Host (DNS rebinding), Origin (cross-site), files (no path traversal).</summary>
public sealed class SecurityTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  static HttpRequestMessage Get(string path, Action<HttpRequestMessage>? change = null)
  {
    var request = new HttpRequestMessage(HttpMethod.Get, path);
    change?.Invoke(request);
    return request;
  }

  [Theory]
  [InlineData("/")]
  [InlineData("/app.js")]
  [InlineData("/api/scenes")]
  [InlineData("/api/status")]
  [InlineData("/api/image.png")]
  public async Task Every_request_without_the_token_is_refused(string path)
  {
    using HttpResponseMessage none = await studio.Stranger.SendAsync(Get(path));
    Assert.Equal(HttpStatusCode.Unauthorized, none.StatusCode);
    using HttpResponseMessage wrong = await studio.Stranger.SendAsync(Get(path, r => r.Headers.Add(AccessGuard.HeaderName, "0123456789abcdef0123456789abcdef")));
    Assert.Equal(HttpStatusCode.Unauthorized, wrong.StatusCode);
  }

  [Fact]
  public async Task The_token_in_the_url_opens_the_page_and_leaves_a_cookie_for_the_pages_requests()
  {
    using HttpResponseMessage page = await studio.Stranger.SendAsync(Get("/?token=" + studio.Server.Token));
    Assert.Equal(HttpStatusCode.OK, page.StatusCode);
    Assert.Contains("<title>GrCis studio</title>", await page.Content.ReadAsStringAsync());
    string cookie = Assert.Single(page.Headers.GetValues("Set-Cookie"));
    Assert.Contains("httponly", cookie, StringComparison.OrdinalIgnoreCase);
    Assert.Contains("samesite=strict", cookie, StringComparison.OrdinalIgnoreCase);

    using HttpResponseMessage api = await studio.Stranger.SendAsync(Get("/api/scenes", r => r.Headers.Add("Cookie", cookie.Split(';')[0])));
    Assert.Equal(HttpStatusCode.OK, api.StatusCode);
  }

  [Theory]
  [InlineData("evil.example")]
  [InlineData("evil.example:80")]
  [InlineData("127.0.0.1.nip.io")]
  public async Task A_host_name_other_than_the_studios_is_refused_even_with_the_token(string host)
  {
    using HttpResponseMessage r = await studio.Client.SendAsync(Get("/api/scenes", m => m.Headers.Host = host));
    Assert.Equal(HttpStatusCode.Forbidden, r.StatusCode);
  }

  [Fact]
  public async Task Requests_from_another_site_are_refused_and_from_the_studios_own_page_accepted()
  {
    using HttpResponseMessage foreign = await studio.Client.SendAsync(Get("/api/scenes", m => m.Headers.Add("Origin", "http://evil.example")));
    Assert.Equal(HttpStatusCode.Forbidden, foreign.StatusCode);
    string own = new Uri(studio.Server.Url).GetLeftPart(UriPartial.Authority);
    using HttpResponseMessage ok = await studio.Client.SendAsync(Get("/api/scenes", m => m.Headers.Add("Origin", own)));
    Assert.Equal(HttpStatusCode.OK, ok.StatusCode);
  }

  [Fact]
  public async Task Only_files_inside_the_given_folders_can_be_read()
  {
    string inside = Path.Combine(studio.ScriptsFolder, "Balls.cs");
    using HttpResponseMessage ok = await studio.Client.GetAsync("/api/file?path=" + Uri.EscapeDataString(inside));
    Assert.Equal(HttpStatusCode.OK, ok.StatusCode);

    foreach (string outside in new[]
    {
      Path.Combine(studio.ScriptsFolder, "..", "secret.txt"),
      Path.Combine(studio.Folder, "secret.txt"),
      studio.ScriptsFolder + "-sibling" + Path.DirectorySeparatorChar + "x.cs",
      "/etc/passwd",
      "scripts/../secret.txt",
    })
    {
      using HttpResponseMessage r = await studio.Client.GetAsync("/api/file?path=" + Uri.EscapeDataString(outside));
      Assert.True(r.StatusCode == HttpStatusCode.Forbidden, $"{outside}: {r.StatusCode}");
    }
  }

  [Fact]
  public void A_studio_bound_to_every_interface_accepts_ip_addresses_but_no_host_names()
  {
    var guard = new AccessGuard("t", AccessGuard.HostsFor("0.0.0.0", 8080, loopback: false), anyAddressPort: 8080);
    Assert.True(Passes(guard, "192.168.1.20:8080"));
    Assert.True(Passes(guard, "[fe80::1]:8080"));
    Assert.False(Passes(guard, "192.168.1.20:8081"));
    Assert.False(Passes(guard, "attacker.example:8080"));
  }

  static bool Passes(AccessGuard guard, string host)
  {
    var context = new Microsoft.AspNetCore.Http.DefaultHttpContext();
    context.Request.Host = new Microsoft.AspNetCore.Http.HostString(host);
    context.Request.Headers[AccessGuard.HeaderName] = "t";
    context.Response.Body = new MemoryStream();
    bool passed = false;
    guard.InvokeAsync(context, _ => { passed = true; return Task.CompletedTask; }).GetAwaiter().GetResult();
    return passed;
  }

  [Fact]
  public async Task The_file_picker_offers_and_adds_only_scripts_inside_the_given_folders()
  {
    string[] files = (await studio.Client.GetFromJsonAsync<string[]>("/api/files"))!;
    string nested = Path.Combine(studio.ScriptsFolder, "more", "Flags.cs");
    Assert.Contains(nested, files);
    Assert.DoesNotContain(files, f => f.EndsWith("Outside.cs", StringComparison.Ordinal));

    using HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path = nested });
    Assert.Equal(HttpStatusCode.OK, added.StatusCode);
    string name = (await added.Content.ReadFromJsonAsync<System.Text.Json.JsonElement>()).GetProperty("name").GetString()!;
    Assert.Contains(name, await studio.Client.GetStringAsync("/api/scenes"));

    using HttpResponseMessage outside = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path = Path.Combine(studio.Folder, "Outside.cs") });
    Assert.Equal(HttpStatusCode.Forbidden, outside.StatusCode);
  }
}
