using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>The extra views of the last render (shown, read out, downloaded) and the history of renders.</summary>
public sealed class ViewsAndHistoryTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  [Fact]
  public async Task Extra_views_are_computed_after_a_render_and_served_as_png_csv_ply_and_read_out()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 40, height = 30 } });
    using HttpResponseMessage computed = await studio.Client.PostAsync("/api/views", null);
    Assert.Equal(HttpStatusCode.OK, computed.StatusCode);
    JsonElement info = await computed.Content.ReadFromJsonAsync<JsonElement>();
    Assert.Equal(40, info.GetProperty("width").GetInt32());

    byte[] png = await studio.Client.GetByteArrayAsync("/api/views/Depth.png");
    Assert.Equal(0x89, png[0]);
    Assert.Equal(40, (png[16] << 24) | (png[17] << 16) | (png[18] << 8) | png[19]);   // IHDR width
    string csv = await studio.Client.GetStringAsync("/api/views/depth.csv");
    Assert.StartsWith("x,y,depth", csv);
    Assert.Equal(1 + 40 * 30, csv.Split('\n', System.StringSplitOptions.RemoveEmptyEntries).Length);
    byte[] ply = await studio.Client.GetByteArrayAsync("/api/views/points.ply");
    Assert.StartsWith("ply", Encoding.ASCII.GetString(ply, 0, 3));

    JsonElement value = await studio.Client.GetFromJsonAsync<JsonElement>("/api/views/value?kind=PrimaryRays&x=20&y=15");
    Assert.Contains("1", value.GetProperty("text").GetString());
    using HttpResponseMessage outside = await studio.Client.GetAsync("/api/views/value?kind=Depth&x=40&y=0");
    Assert.Equal(HttpStatusCode.BadRequest, outside.StatusCode);
    using HttpResponseMessage unknown = await studio.Client.GetAsync("/api/views/Colour.png");
    Assert.Equal(HttpStatusCode.NotFound, unknown.StatusCode);
  }

  [Fact]
  public async Task Noise_view_reads_out_the_path_traced_renders_standard_error()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 32, height = 24, samplesPerPixel = 16 }, algorithm = "path" });
    using HttpResponseMessage computed = await studio.Client.PostAsync("/api/views", null);
    Assert.Equal(HttpStatusCode.OK, computed.StatusCode);
    Assert.Contains("Noise", (await computed.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("kinds").EnumerateArray().Select(k => k.GetString()));
    JsonElement value = await studio.Client.GetFromJsonAsync<JsonElement>("/api/views/value?kind=Noise&x=16&y=12");
    Assert.Contains("noise ±", value.GetProperty("text").GetString());
    Assert.StartsWith("x,y,standard_error", await studio.Client.GetStringAsync("/api/views/noise.csv"));
    Assert.Equal(0x89, (await studio.Client.GetByteArrayAsync("/api/views/Noise.png"))[0]);
    Assert.Contains("value=\"Noise\"", await studio.Client.GetStringAsync("/"));
  }

  [Fact]
  public async Task Back_and_forward_show_the_earlier_and_later_renders()
  {
    await studio.RenderAndWait(new { scene = "Five balls", settings = new { width = 24, height = 16 } });
    byte[] first = await studio.Client.GetByteArrayAsync("/api/image.png");
    await studio.RenderAndWait(new { scene = "Flags", settings = new { width = 24, height = 16 } });
    byte[] second = await studio.Client.GetByteArrayAsync("/api/image.png");
    Assert.NotEqual(first, second);

    using HttpResponseMessage back = await studio.Client.PostAsync("/api/history/back", null);
    Assert.Equal(HttpStatusCode.OK, back.StatusCode);
    JsonElement list = await back.Content.ReadFromJsonAsync<JsonElement>();
    Assert.True(list.GetProperty("canGoForward").GetBoolean());
    Assert.StartsWith("Five balls", list.GetProperty("items")[list.GetProperty("position").GetInt32()].GetProperty("label").GetString());
    Assert.Equal(first, await studio.Client.GetByteArrayAsync("/api/image.png"));

    using HttpResponseMessage forward = await studio.Client.PostAsync("/api/history/forward", null);
    Assert.Equal(HttpStatusCode.OK, forward.StatusCode);
    Assert.Equal(second, await studio.Client.GetByteArrayAsync("/api/image.png"));
    using HttpResponseMessage beyond = await studio.Client.PostAsync("/api/history/forward", null);
    Assert.Equal(HttpStatusCode.Conflict, beyond.StatusCode);
  }
}
