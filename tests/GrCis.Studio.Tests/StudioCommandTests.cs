using System;
using System.IO;
using System.Net;
using System.Net.Http;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Cli;

namespace GrCis.Studio.Tests;

/// <summary><c>grcis studio</c>: one line with the URL on stdout, serves until Ctrl+C, then exits 130.</summary>
public class StudioCommandTests
{
  /// <summary>Runs <c>grcis studio</c> with <paramref name="options"/> in the background until its URL line is out (60 s at most: it comes once the editor is warm).</summary>
  static async Task<(Task<int> Run, string Url, StringWriter Error)> Start(CancellationTokenSource cancel, params string[] options)
  {
    var output = new StringWriter();
    var error = new StringWriter();
    var env = new CliEnvironment(TextWriter.Synchronized(output), TextWriter.Synchronized(error)) { Cancel = cancel.Token };
    Task<int> run = Task.Run(() => Program.Run(["studio", .. options], env));
    string url = "";
    for (int i = 0; i < 1200 && url.Length == 0 && !run.IsCompleted; i++)
    {
      await Task.Delay(50);
      url = output.ToString().Trim();
    }
    return (run, url, error);
  }

  [Fact]
  public async Task Studio_prints_its_url_serves_and_exits_130_on_ctrl_c()
  {
    using var cancel = new CancellationTokenSource();
    (Task<int> run, string url, _) = await Start(cancel, "--port", "0", "--no-open");
    Assert.Matches(@"^http://127\.0\.0\.1:\d+/\?token=[0-9a-f]{32}$", url);
    using (var client = new HttpClient())
    {
      using HttpResponseMessage page = await client.GetAsync(url);
      Assert.Equal(HttpStatusCode.OK, page.StatusCode);
    }

    cancel.Cancel();
    Assert.Equal(130, await run.WaitAsync(TimeSpan.FromSeconds(30)));
    using var after = new HttpClient();
    await Assert.ThrowsAsync<HttpRequestException>(() => after.GetAsync(url));
  }

  [Fact]
  public async Task A_host_other_than_loopback_warns_and_still_needs_the_token()
  {
    using var cancel = new CancellationTokenSource();
    (Task<int> run, string url, StringWriter error) = await Start(cancel, "--host", "0.0.0.0", "--port", "0", "--no-open");
    Assert.Contains("warning: --host 0.0.0.0", error.ToString());
    var uri = new Uri(url);
    using (var client = new HttpClient())
    {
      using HttpResponseMessage without = await client.GetAsync($"http://127.0.0.1:{uri.Port}/api/status");
      Assert.Equal(HttpStatusCode.Unauthorized, without.StatusCode);
      using HttpResponseMessage with = await client.GetAsync($"http://127.0.0.1:{uri.Port}/{uri.Query}");
      Assert.Equal(HttpStatusCode.OK, with.StatusCode);
    }
    cancel.Cancel();
    Assert.Equal(130, await run.WaitAsync(TimeSpan.FromSeconds(30)));
  }

  [Theory]
  [InlineData("--port", "70000", "--port")]
  [InlineData("--host", "not-an-address", "--host")]
  public void Bad_options_are_usage_errors(string option, string value, string named)
  {
    var error = new StringWriter();
    int code = Program.Run(["studio", option, value, "--no-open"], new StringWriter(), error);
    Assert.Equal(2, code);
    Assert.Contains(named, error.ToString());
  }

  [Fact]
  public void A_missing_script_is_a_usage_error_naming_it()
  {
    var error = new StringWriter();
    int code = Program.Run(["studio", "no-such-script.cs", "--no-open"], new StringWriter(), error);
    Assert.Equal(2, code);
    Assert.Contains("no-such-script.cs", error.ToString());
  }

  [Fact]
  public void A_port_in_use_is_a_failure_naming_it()
  {
    using var taken = new System.Net.Sockets.TcpListener(IPAddress.Loopback, 0);
    taken.Start();
    int port = ((IPEndPoint)taken.LocalEndpoint).Port;
    var error = new StringWriter();
    int code = Program.Run(["studio", "--port", port.ToString(System.Globalization.CultureInfo.InvariantCulture), "--no-open"], new StringWriter(), error);
    Assert.Equal(1, code);
    Assert.Contains($"cannot listen on 127.0.0.1:{port}", error.ToString());
  }
}
