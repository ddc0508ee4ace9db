using System;
using System.Collections.Generic;
using System.Linq;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using OpenQA.Selenium.Interactions;
using static GrCis.Studio.Tests.BrowserTests;

namespace GrCis.Studio.Tests;

/// <summary>
/// Hover and pick in the 3D view (issue 42): a hovered surface named beside the pointer, the part a probed pixel's ray hit
/// tinted, a click on a surface probing the pixel that sees it (or saying none does), and the points layer.
/// </summary>
public sealed partial class BrowserScene3dTests
{
  /// <summary>What <paramref name="expression"/> (over the page's module <c>pane3d.js</c>, as <c>m</c>) gives, as JSON.</summary>
  static JsonElement Pane3d(ChromeDriver browser, string expression) => JsonDocument.Parse((string)((IJavaScriptExecutor)browser).ExecuteAsyncScript($$"""
    const done = arguments[arguments.length - 1];
    import('./pane3d.js').then(async m => done(JSON.stringify(await ({{expression}}) ?? null)));
    """)!).RootElement;

  static string? PaneData(ChromeDriver browser, string key) =>
    (string?)Js(browser, "return document.getElementById('rays3dPane').dataset[arguments[0]] ?? null;", key);

  /// <summary>The pointer moved to the client point (<paramref name="x"/>, <paramref name="y"/>) of the 3D view.</summary>
  static Actions To3d(ChromeDriver browser, double x, double y)
  {
    IWebElement canvas = browser.FindElement(By.Id("rays3d"));
    double[] r = ((IReadOnlyCollection<object>)Js(browser, "const r = document.getElementById('rays3d').getBoundingClientRect(); return [r.left, r.top, r.width, r.height];")!)
      .Select(Convert.ToDouble).ToArray();
    return new Actions(browser).MoveToElement(canvas, (int)Math.Round(x - r[0] - r[2] / 2), (int)Math.Round(y - r[1] - r[3] / 2));
  }

  static (double X, double Y) ScreenOf(ChromeDriver browser, string part)
  {
    JsonElement p = Pane3d(browser, $"m.screenOf('{part}')");
    return (p.GetProperty("x").GetDouble(), p.GetProperty("y").GetDouble());
  }

  [SkippableFact]
  public void Hovering_a_surface_names_it_beside_the_pointer_and_a_probed_pixel_tints_the_part_its_ray_hit()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Render(browser, "TwoSpheres.cs", 320, 240);
    Open3d(browser);

    // The glass ball, nearest to the orbit's start (beside the render's camera): its name, class and material's colour.
    (double x, double y) = ScreenOf(browser, "Sphere 1");
    To3d(browser, x, y).Perform();
    IWebElement label = browser.FindElement(By.Id("hover3d"));
    Until(browser, () => label.Displayed && label.Text.StartsWith("Sphere 1", StringComparison.Ordinal), "the hovered ball's name");
    output.WriteLine(label.Text.Replace('\n', '|'));
    Shot(browser, "studio-3d-hover.png", docs: true);
    Assert.Equal(["Sphere 1", "Sphere", "colour (0.00, 0.20, 0.10)"], label.Text.Split('\n'));
    // Beside the pointer, not under it.
    double[] box = ((IReadOnlyCollection<object>)Js(browser, "const r = document.getElementById('hover3d').getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom];")!)
      .Select(Convert.ToDouble).ToArray();
    Assert.False(x >= box[0] && x <= box[2] && y >= box[1] && y <= box[3], $"the label ({string.Join(", ", box)}) covers the pointer at ({x}, {y})");
    new Actions(browser).MoveToElement(browser.FindElement(By.Id("render"))).Perform();
    Until(browser, () => !label.Displayed, "the label gone with the pointer");

    // The glass ball's pixel: its part tinted in 3D, as the probe names it; the sky's pixel: none.
    using HttpClient client = StudioFixture.ClientOf(studio.Server);
    string? glass = client.GetFromJsonAsync<JsonElement>("/api/probe?x=150&y=130").GetAwaiter().GetResult().GetProperty("partName").GetString();
    Assert.Equal("Sphere 1", glass);
    ClickPixel(browser, 150, 130);
    Until(browser, () => PaneData(browser, "highlight") == glass, "the glass ball tinted");
    Shot(browser, "studio-3d-highlight.png");
    Assert.True(browser.FindElement(By.Id("probeMark")).Displayed);
    ClickPixel(browser, 2, 2);
    Until(browser, () => PaneData(browser, "highlight") == "", "no part tinted for the sky");
    browser.FindElement(By.Id("show3d")).Click();
  }

  [SkippableFact]
  public void A_click_on_a_surface_in_3d_probes_the_pixel_that_sees_it_or_says_that_none_does()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Render(browser, "TwoSpheres.cs", 320, 240);
    Open3d(browser);
    browser.FindElement(By.Id("fromCamera")).Click();

    (double x, double y) = ScreenOf(browser, "Sphere 2");
    To3d(browser, x, y).Click().Perform();
    Until(browser, () => PaneData(browser, "pickVisible") != null, "the pick's answer");
    Assert.Equal(("Sphere 2", "true"), (PaneData(browser, "pickPart"), PaneData(browser, "pickVisible")));
    Shot(browser, "studio-3d-pick.png");
    // The pixel probed is one whose primary ray hits that ball; the image and the rays show it, as for a click on the image.
    int[] pixel = PaneData(browser, "pickPixel")!.Split(',').Select(int.Parse).ToArray();
    using HttpClient client = StudioFixture.ClientOf(studio.Server);
    Assert.Equal("Sphere 2", client.GetFromJsonAsync<JsonElement>($"/api/probe?x={pixel[0]}&y={pixel[1]}").GetAwaiter().GetResult().GetProperty("partName").GetString());
    Assert.StartsWith($"pixel [{pixel[0]}, {pixel[1]}]", browser.FindElement(By.Id("rays")).Text);
    Assert.Equal("Sphere 2", PaneData(browser, "highlight"));
    Assert.True(Convert.ToInt32(PaneData(browser, "raySegments")) >= 2);

    // The far side of that ball (centre (1.5, 0.2, 2.4), radius 1.2, seen along (0, −0.18, 1)): its pixel sees the near side.
    string Pick(string point)
    {
      Js(browser, "delete document.getElementById('rays3dPane').dataset.pickVisible;");
      Pane3d(browser, $"m.pickAt(1, {point})");
      Assert.Equal("false", PaneData(browser, "pickVisible"));
      return browser.FindElement(By.Id("pick3d")).Text;
    }
    double n = Math.Sqrt(1 + 0.18 * 0.18);
    string behind = Pick(FormattableString.Invariant($"[1.5, {0.2 - 1.2 * 0.18 / n}, {2.4 + 1.2 / n}]"));
    Assert.Contains("Sphere 2 here is not visible from the camera", behind);
    Assert.Contains("sees Sphere 2 in front of this point", behind);
    string outside = Pick("[1.5, 0.2, -20]");
    Assert.Contains("outside its view", outside);
    Assert.Equal("", PaneData(browser, "pickPixel"));
    browser.FindElement(By.Id("show3d")).Click();
  }

  [SkippableFact]
  public void The_points_layer_shows_the_renders_hits_is_remembered_and_gives_its_memory_back()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Render(browser, "TwoSpheres.cs", 64, 48);
    Dictionary<string, int> shown = Open3d(browser);
    Assert.Equal(0, shown["points"]);
    int before = Pane3d(browser, "m.memory()").GetProperty("geometries").GetInt32();

    using HttpClient client = StudioFixture.ClientOf(studio.Server);
    int count = client.GetFromJsonAsync<JsonElement>("/api/scene/points?max=40000").GetAwaiter().GetResult().GetProperty("count").GetInt32();
    browser.FindElement(By.CssSelector("#layers3d [data-layer=points]")).Click();
    Until(browser, () => PaneData(browser, "points") == count.ToString(System.Globalization.CultureInfo.InvariantCulture), $"{count} points");
    Assert.Contains("points", Pane3d(browser, "m.visibleLayers()").EnumerateArray().Select(e => e.GetString()));
    // Drawn once: one more geometry on the GPU.
    Pane3d(browser, "m.snapshot() && 0");
    Assert.Equal(before + 1, Pane3d(browser, "m.memory()").GetProperty("geometries").GetInt32());

    browser.Navigate().Refresh();
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Until(browser, () => browser.FindElement(By.Id("show3d")).Displayed, "the 3D button");
    Open3d(browser);
    Assert.True((bool)Js(browser, "return document.querySelector('#layers3d [data-layer=points]').checked;")!);
    Until(browser, () => PaneData(browser, "points") == count.ToString(System.Globalization.CultureInfo.InvariantCulture), "the points again after a reload");

    // A new render's points replace the old ones in the open pane. Optics' lens is the intersection of two large balls:
    // the surfaces show the balls, the points the thin lens.
    browser.FindElement(By.CssSelector("#layers3d [data-layer=surfaces]")).Click();
    string before3d = PaneData(browser, "scene")!;
    Render(browser, "Optics.cs", 320, 240);
    Until(browser, () => PaneData(browser, "scene") != before3d, "Optics in the open pane");
    int optics = client.GetFromJsonAsync<JsonElement>("/api/scene/points?max=40000").GetAwaiter().GetResult().GetProperty("count").GetInt32();
    Until(browser, () => PaneData(browser, "points") == optics.ToString(System.Globalization.CultureInfo.InvariantCulture), $"Optics' {optics} points");
    System.Threading.Thread.Sleep(200);
    Shot(browser, "studio-3d-points.png", docs: true);
    browser.FindElement(By.Id("show3d")).Click();
    Assert.Equal(0, Pane3d(browser, "m.memory()").GetProperty("geometries").GetInt32());
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
  }
}
