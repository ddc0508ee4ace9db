using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using Deque.AxeCore.Commons;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using OpenQA.Selenium.Interactions;
using static GrCis.Studio.Tests.BrowserTests;

namespace GrCis.Studio.Tests;

/// <summary>
/// The studio's layout on a laptop's screen (1280x720) and a desktop's (1920x1080), and in smaller windows (1024x700,
/// 800x600: every header control whole, the image fitted), in headless chromium: the image fitted
/// and centred, fully visible beside the 3D view and beside the editor, the header the same height after renders, the
/// keys for Render and Stop, and axe-core's accessibility rules with no serious or critical violation, in the dark and
/// the light theme. The screenshots of the 1280x720 run are the ones docs/studio.md shows
/// (<c>GRCIS_WRITE_SCREENSHOTS=1</c> writes them to docs/images).
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class BrowserLayoutTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  internal static double[] Rect(IWebDriver browser, string id) => ((IReadOnlyCollection<object>)Js(browser,
    "const r = document.getElementById(arguments[0]).getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom];", id)!)
    .Select(Convert.ToDouble).ToArray();

  internal static string Show(double[] r) => "[" + string.Join(", ", r.Select(v => v.ToString("0.#", System.Globalization.CultureInfo.InvariantCulture))) + "]";

  /// <summary>The whole image inside the view and inside the window, centred in the view, as large as fits.</summary>
  internal static void AssertImageFittedAndVisible(IWebDriver browser, int width, int height)
  {
    double[] image = Rect(browser, "canvas"), view = Rect(browser, "view");
    Assert.True(image[0] >= view[0] - 0.5 && image[1] >= view[1] - 0.5 && image[2] <= view[2] + 0.5 && image[3] <= view[3] + 0.5,
                $"image {Show(image)} outside the view {Show(view)}");
    Assert.True(view[0] >= 0 && view[1] >= 0 && view[2] <= width && view[3] <= height, $"view {Show(view)} outside the {width}x{height} window");
    Assert.InRange(image[0] - view[0] - (view[2] - image[2]), -2.0, 2.0);
    Assert.InRange(image[1] - view[1] - (view[3] - image[3]), -2.0, 2.0);
    // As large as fits (8 px of margin, view.js, from the view's sides or from its top and bottom), or 1:1 where that is
    // smaller: fitting does not enlarge by default.
    double zoom = (image[2] - image[0]) / Convert.ToDouble(Js(browser, "return document.getElementById('canvas').width;"));
    Assert.True(Math.Min(image[0] - view[0], image[1] - view[1]) <= 9.0 || Math.Abs(zoom - 1) < 0.01,
                $"image {Show(image)} smaller than fits in {Show(view)}, at {zoom:0.###}:1");
    Assert.True(zoom <= 1.001, $"image {Show(image)} enlarged {zoom:0.###} times");
    // Nothing is drawn over it: the element at its centre is the image.
    Assert.Equal("canvas", (string)Js(browser, """
      const r = document.getElementById('canvas').getBoundingClientRect();
      return document.elementFromPoint((r.left + r.right) / 2, (r.top + r.bottom) / 2).id;
      """)!);
  }

  static void AssertApart(double[] a, double[] b, string what) =>
    Assert.True(a[2] <= b[0] + 0.5 || b[2] <= a[0] + 0.5 || a[3] <= b[1] + 0.5 || b[3] <= a[1] + 0.5, $"{what}: {Show(a)} and {Show(b)} overlap");

  /// <summary>axe-core (the copy Deque.AxeCore.Commons ships) run on the page as it is: no serious or critical violation,
  /// or none at all when <paramref name="anyImpact"/>.</summary>
  internal static void AssertAccessible(ChromeDriver browser, string state, bool anyImpact = false)
  {
    if ((bool)Js(browser, "return typeof window.axe === 'undefined';")!)
      Js(browser, new BundledAxeScriptProvider().GetScript());
    string json = (string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      axe.run(document, { resultTypes: ['violations'] })
        .then(r => done(JSON.stringify(r.violations.map(v => ({ id: v.id, impact: v.impact, help: v.help,
          nodes: v.nodes.map(n => n.target.join(' ') + ': ' + n.failureSummary) })))))
        .catch(e => done(JSON.stringify([{ id: 'axe-failed', impact: 'critical', help: String(e), nodes: [] }])));
      """)!;
    using JsonDocument violations = JsonDocument.Parse(json);
    string[] bad = violations.RootElement.EnumerateArray()
      .Where(v => anyImpact || v.GetProperty("impact").GetString() is "serious" or "critical")
      .Select(v => $"{v.GetProperty("id").GetString()} ({v.GetProperty("impact").GetString()}): {v.GetProperty("help").GetString()}\n    " +
                   string.Join("\n    ", v.GetProperty("nodes").EnumerateArray().Take(5).Select(n => n.GetString())))
      .ToArray();
    Assert.True(bad.Length == 0, $"axe-core, {state}:\n" + string.Join("\n", bad));
  }

  static double HeaderHeight(IWebDriver browser) => Convert.ToDouble(Js(browser, "return document.querySelector('header').getBoundingClientRect().height;"));

  void WaitIdle(IWebDriver browser, string what) =>
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.Length > 0 && !browser.FindElement(By.Id("stop")).Enabled, what, studio.Server.Session);

  /// <summary>Every visible control of the header whole inside the header and the window (none cut off or under another), the parameters wide enough to type in.</summary>
  static void AssertHeaderWhole(IWebDriver browser, int width, string state)
  {
    string cut = (string)Js(browser, """
      const header = document.querySelector('header').getBoundingClientRect(), out = [], seen = [];
      for (const e of document.querySelectorAll('header button, header a, header select, header input')) {
        if (e.closest('[hidden]') || e.offsetParent === null) continue;
        const r = e.getBoundingClientRect(), name = e.id || e.textContent;
        if (r.left < 0 || r.right > innerWidth || r.top < header.top || r.bottom > header.bottom) out.push(name);
        for (const [other, o] of seen)
          if (r.left < o.right - 0.5 && o.left < r.right - 0.5 && r.top < o.bottom - 0.5 && o.top < r.bottom - 0.5) out.push(name + ' over ' + other);
        seen.push([name, r]);
      }
      return out.join(', ');
      """)!;
    Assert.True(cut.Length == 0, $"{state}, {width} px wide: cut off: {cut}");
    double[] param = Rect(browser, "param");
    Assert.True(param[2] - param[0] >= 100, $"{state}, {width} px wide: the parameters field is {param[2] - param[0]:0} px wide");
  }

  [SkippableTheory]
  [InlineData(1024, 700)]
  [InlineData(800, 600)]
  public void In_a_smaller_window_every_header_control_stays_whole_and_the_image_fits(int width, int height)
  {
    using ChromeDriver browser = Browser(width, height);
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");   // whatever ran before
    AssertHeaderWhole(browser, width, "a built-in scene");
    double header = HeaderHeight(browser);

    // A script shows Edit too, the header's widest state.
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
    RenderIn(browser, studio.Server.Session, "Balls", 320, 240);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button");
    AssertHeaderWhole(browser, width, "a script");
    Assert.Equal(header, HeaderHeight(browser));
    AssertImageFittedAndVisible(browser, width, height);
    AssertApart(Rect(browser, "canvas"), Rect(browser, "settingsPanel"), "the image and the settings");
    Shot(browser, $"studio-render-{width}x{height}.png");
  }

  [SkippableTheory]
  [InlineData(1280, 720)]
  [InlineData(1920, 1080)]
  public void The_image_is_fitted_and_centred_beside_every_pane_and_the_page_passes_axe(int width, int height)
  {
    bool docs = width == 1280;
    string suffix = docs ? "" : $"-{width}x{height}";
    using ChromeDriver browser = Browser(width, height);
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Assert.Equal(new long[] { width, height }, ((IReadOnlyCollection<object>)Js(browser, "return [innerWidth, innerHeight];")!).Select(Convert.ToInt64));
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");   // whatever ran before
    double header = HeaderHeight(browser);

    // A finished render: fitted and centred by default; the header as high as before.
    RenderIn(browser, studio.Server.Session, "Five balls", 320, 240);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 320, "the image");
    AssertImageFittedAndVisible(browser, width, height);
    Assert.Equal(header, HeaderHeight(browser));
    Shot(browser, $"studio-render{suffix}.png", docs);
    AssertAccessible(browser, "a finished render");

    // The probe and its rays in 3D: the pane beside the image, which is fitted again into the narrower view.
    ClickPixel(browser, 160, 120);
    Until(browser, () => browser.FindElement(By.Id("rays")).Text.StartsWith("pixel [160, 120]", StringComparison.Ordinal), "the ray tree");
    browser.FindElement(By.Id("show3d")).Click();
    Until(browser, () => browser.FindElement(By.Id("rays3dPane")).Displayed, "the 3D view");
    Until(browser, () => Rect(browser, "canvas")[2] <= Rect(browser, "view")[2] + 0.5, "the image fitted beside the 3D view");
    AssertImageFittedAndVisible(browser, width, height);
    AssertApart(Rect(browser, "canvas"), Rect(browser, "rays3dPane"), "the image and the 3D view");
    System.Threading.Thread.Sleep(200);
    Shot(browser, $"studio-probe-3d{suffix}.png", docs);
    browser.FindElement(By.Id("show3d")).Click();

    // The editor with an error: beside the image, not over it; the error stays above the image until dismissed.
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), "// Five balls\nRendering.Scenes.FiveBalls(scene);\n");
    RenderIn(browser, studio.Server.Session, "Balls", 320, 240);
    AssertHeaderWhole(browser, width, "a script");
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1, "the editor");
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", "// Five balls\nRendering.Scenes.FiveBals(scene);\n");
    browser.FindElement(By.Id("save")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count > 0 && browser.FindElement(By.Id("messageBox")).Displayed, "the error");
    Until(browser, () => Rect(browser, "canvas")[2] <= Rect(browser, "view")[2] + 0.5, "the image fitted beside the editor");
    AssertImageFittedAndVisible(browser, width, height);
    AssertApart(Rect(browser, "canvas"), Rect(browser, "editorPane"), "the image and the editor");
    AssertApart(Rect(browser, "canvas"), Rect(browser, "messageBox"), "the image and the message");
    Assert.Contains("CS0117", browser.FindElement(By.Id("messages")).Text);
    Assert.Equal(header, HeaderHeight(browser));
    Shot(browser, $"studio-editor-error{suffix}.png", docs: true);
    AssertAccessible(browser, "the editor with an error");
    browser.FindElement(By.Id("dismiss")).Click();
    Assert.False(browser.FindElement(By.Id("messageBox")).Displayed);
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", "// Five balls\nRendering.Scenes.FiveBalls(scene);\n");
    browser.FindElement(By.Id("save")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count == 0, "the fixed script");
    WaitIdle(browser, "the fixed script's render");
    browser.FindElement(By.Id("closeEditor")).Click();

    // Path tracing in passes, started with F5 and stopped with Esc: the status bar shows the samples so far and the noise.
    Js(browser, """
      const s = document.getElementById('scene'); s.value = 'Five balls'; s.dispatchEvent(new Event('change'));
      document.getElementById('width').value = 480; document.getElementById('height').value = 360;
      document.getElementById('algorithm').value = 'path'; document.getElementById('spp').value = 400;
      document.getElementById('stats').textContent = '';
      """);
    new Actions(browser).SendKeys(Keys.F5).Perform();
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.Contains("so far, noise", StringComparison.Ordinal) &&
                         (long)Js(browser, "return document.getElementById('canvas').width;")! == 480, "a pass with its noise");
    Until(browser, () => !browser.FindElement(By.Id("stats")).Text.StartsWith("1 spp", StringComparison.Ordinal) ||
                         !browser.FindElement(By.Id("stop")).Enabled, "the second pass");
    AssertImageFittedAndVisible(browser, width, height);
    Shot(browser, $"studio-passes{suffix}.png", docs);
    new Actions(browser).SendKeys(Keys.Escape).Perform();
    // Idle: "stopped" once the stopped render has ended ("" when it had finished before Esc reached it).
    Until(browser, () => !browser.FindElement(By.Id("stop")).Enabled && browser.FindElement(By.Id("phase")).Text is "" or "stopped", "idle after Esc");
    Assert.Equal(header, HeaderHeight(browser));

    // A short full render and its noise view, in the light theme.
    Js(browser, "document.getElementById('spp').value = 16; document.getElementById('width').value = 320; document.getElementById('height').value = 240;");
    RenderIn(browser, studio.Server.Session, "Five balls", 320, 240);
    Js(browser, "const k = document.getElementById('view-kind'); k.value = 'Noise'; k.dispatchEvent(new Event('change'));");
    Until(browser, () => (string?)Js(browser, "return document.getElementById('viewPng').getAttribute('href');") == "api/views/Noise.png" &&
                         !browser.FindElement(By.Id("messageBox")).Displayed, "the noise view");
    browser.FindElement(By.Id("theme")).Click();
    Assert.Equal("light", (string)Js(browser, "return document.documentElement.dataset.theme;")!);
    System.Threading.Thread.Sleep(300);
    AssertImageFittedAndVisible(browser, width, height);
    Shot(browser, $"studio-noise-light{suffix}.png", docs);
    AssertAccessible(browser, "the light theme");
    Assert.Equal(header, HeaderHeight(browser));
    browser.FindElement(By.Id("theme")).Click();
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");
  }

  [SkippableFact]
  public void Every_control_is_reached_with_Tab_and_has_a_name()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Shot(browser, "studio-start.png");
    // Every visible, enabled control, in the order Tab goes through the page.
    var controls = ((IReadOnlyCollection<object>)Js(browser, """
      return [...document.querySelectorAll('button, input, select, a[href], summary')]
        .filter(e => !e.disabled && e.checkVisibility()).map(e => e.id || e.textContent.trim());
      """)!).Cast<string>().ToList();
    var reached = new HashSet<string>();
    browser.FindElement(By.TagName("body")).Click();
    for (int i = 0; i < controls.Count + 5; i++)
    {
      new Actions(browser).SendKeys(Keys.Tab).Perform();
      reached.Add((string)Js(browser, "const e = document.activeElement; return e.id || e.textContent.trim();")!);
    }
    string[] missed = controls.Where(c => !reached.Contains(c)).ToArray();
    Assert.True(missed.Length == 0, "not reached with Tab: " + string.Join(", ", missed));
    AssertAccessible(browser, "the page as loaded");
  }
}
