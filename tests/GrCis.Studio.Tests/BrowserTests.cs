using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using GrCis.Cli;
using GrCis.TestSupport;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using OpenQA.Selenium.Interactions;
using Rendering.Imaging;

namespace GrCis.Studio.Tests;

/// <summary>
/// The studio in a real browser (Debian's chromium and chromium-driver, headless): render Five balls and
/// compare the shown pixels with <c>grcis render</c>'s PNG, click a pixel for its ray tree and 3D view,
/// save a script with a typo and see the error at its line, fix it and see a new image; path-trace it in passes
/// and look at its noise. Screenshots of
/// each step are written beside the test assembly (<c>screenshots/</c>).
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed partial class BrowserTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  static readonly string Shots = Path.Combine(AppContext.BaseDirectory, "screenshots");

  /// <summary>Headless chromium whose page (the viewport, what a screenshot shows) is <paramref name="width"/> by
  /// <paramref name="height"/> CSS pixels; the default is a laptop's 1280x720.</summary>
  internal static ChromeDriver Browser(int width = 1280, int height = 720)
  {
    string chromium = RequiredTool.Find("chromium", "chromium");
    string driver = RequiredTool.Find("chromedriver", "chromium-driver");
    var options = new ChromeOptions { BinaryLocation = chromium };
    options.AddArguments("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", $"--window-size={width},{height}",
                         "--force-color-profile=srgb", "--force-device-scale-factor=1", "--hide-scrollbars");
    ChromeDriverService service = ChromeDriverService.CreateDefaultService(Path.GetDirectoryName(driver)!, Path.GetFileName(driver));
    service.SuppressInitialDiagnosticInformation = true;
    service.HideCommandPromptWindow = true;
    var browser = new ChromeDriver(service, options, TimeSpan.FromSeconds(60));
    Resize(browser, width, height);
    return browser;
  }

  /// <summary>Makes the page of <paramref name="browser"/> <paramref name="width"/> by <paramref name="height"/> CSS pixels.</summary>
  internal static void Resize(ChromeDriver browser, int width, int height)
  {
    browser.Manage().Window.Size = new System.Drawing.Size(width, height);
    // The window's size includes what the browser itself draws around the page: the page is made the size asked for.
    var inner = (IReadOnlyCollection<object>)Js(browser, "return [window.innerWidth, window.innerHeight];")!;
    long[] page = inner.Select(Convert.ToInt64).ToArray();
    if (page[0] != width || page[1] != height)
    {
      System.Drawing.Size outer = browser.Manage().Window.Size;
      browser.Manage().Window.Size = new System.Drawing.Size(outer.Width + width - (int)page[0], outer.Height + height - (int)page[1]);
    }
  }

  /// <param name="server">What the studio's own state says, added to the message on time-out (<see cref="StudioState.Describe"/>); null = nothing.</param>
  internal static void Until(IWebDriver browser, Func<bool> condition, string what, StudioSession? server = null)
  {
    var deadline = DateTime.UtcNow + TimeSpan.FromSeconds(60);
    while (!condition())
    {
      if (DateTime.UtcNow > deadline)
        throw new TimeoutException($"waited 60 s for {what}; page messages: {Js(browser, "return document.getElementById('messages').textContent;")}" +
                                   (server == null ? "" : $"; {StudioState.Describe(server)}"));
      System.Threading.Thread.Sleep(50);
    }
  }

  /// <summary>A screenshot beside the test assembly (<c>screenshots/</c>); one the docs show is also written to
  /// <c>docs/images/</c> when <c>GRCIS_WRITE_SCREENSHOTS=1</c>, so the docs show the page as it ships.</summary>
  internal static void Shot(ChromeDriver browser, string name, bool docs = false)
  {
    Directory.CreateDirectory(Shots);
    Screenshot shot = browser.GetScreenshot();
    shot.SaveAsFile(Path.Combine(Shots, name));
    if (docs && Environment.GetEnvironmentVariable("GRCIS_WRITE_SCREENSHOTS") == "1")
      shot.SaveAsFile(Path.Combine(DocsImages(), name));
  }

  /// <summary>The repository's <c>docs/images</c>, found above the test assembly.</summary>
  static string DocsImages()
  {
    for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
      if (File.Exists(Path.Combine(dir.FullName, "GrCis.sln")))
        return Path.Combine(dir.FullName, "docs", "images");
    throw new InvalidOperationException("GRCIS_WRITE_SCREENSHOTS=1, but no GrCis.sln above " + AppContext.BaseDirectory);
  }

  /// <summary>Clicks the image's pixel (<paramref name="x"/>, <paramref name="y"/>) where it is on screen, at whatever zoom.</summary>
  internal static void ClickPixel(ChromeDriver browser, int x, int y)
  {
    IWebElement canvas = browser.FindElement(By.Id("canvas"));
    double[] box = ((IReadOnlyCollection<object>)Js(browser,
      "const c = document.getElementById('canvas'), r = c.getBoundingClientRect(); return [r.width, r.height, r.width / c.width];")!)
      .Select(Convert.ToDouble).ToArray();
    new Actions(browser).MoveToElement(canvas, (int)Math.Floor((x + 0.5) * box[2] - box[0] / 2), (int)Math.Floor((y + 0.5) * box[2] - box[1] / 2))
      .Click().Perform();
  }

  internal static object? Js(IWebDriver browser, string script, params object[] args) => ((IJavaScriptExecutor)browser).ExecuteScript(script, args);

  /// <summary>Opens the studio's page and adds the script file <paramref name="path"/> to its scene list through the file picker.</summary>
  void OpenAndAdd(ChromeDriver browser, string path)
  {
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    browser.FindElement(By.Id("open")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#files option")).Count > 0, "the file picker");
    Js(browser, "document.getElementById('files').value = arguments[0];", path);
    browser.FindElement(By.Id("add")).Click();
    // Added once the scene list shows it selected (until then Edit would open the script selected before).
    Until(browser, () => (string?)Js(browser, "return document.getElementById('scene').selectedOptions[0]?.textContent;") == Path.GetFileName(path),
          "the added script selected");
  }

  /// <summary>Renders <paramref name="scene"/> at the size given and waits for its statistics and the Stop button disabled;
  /// on time-out the message has the state of <paramref name="server"/>, the studio the page talks to.</summary>
  internal static void RenderIn(ChromeDriver browser, StudioSession server, string scene, int width, int height)
  {
    Js(browser, "const s = document.getElementById('scene'); s.value = arguments[0]; s.dispatchEvent(new Event('change'));", scene);
    Js(browser, "document.getElementById('width').value = arguments[0]; document.getElementById('height').value = arguments[1];", width, height);
    Js(browser, "document.getElementById('stats').textContent = '';");
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.StartsWith($"{width}x{height}", StringComparison.Ordinal) &&
                         !browser.FindElement(By.Id("stop")).Enabled, $"the render of {scene}", server);
  }

  [SkippableFact]
  public void The_page_renders_probes_and_edits_as_a_user_does()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");

    // 1. Five balls, shown exactly as grcis render saves it.
    RenderIn(browser, studio.Server.Session, "Five balls", 160, 120);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 160, "the image");
    var shown = ((IReadOnlyCollection<object>)Js(browser,
      "const c = document.getElementById('canvas'); return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);")!)
      .Select(Convert.ToByte).ToArray();
    string png = Path.Combine(studio.Folder, "five-balls.png");
    Assert.Equal(0, Program.Run(["render", "Five balls", "--size", "160x120", "-q", "-o", png], new StringWriter(), new StringWriter()));
    Rgb8Image expected = ImageFile.LoadRgb8(png);
    int differing = 0;
    for (int y = 0; y < 120; y++)
      for (int x = 0; x < 160; x++)
      {
        (byte r, byte g, byte b) = expected.GetPixel(x, y);
        int i = 4 * (y * 160 + x);
        if (shown[i] != r || shown[i + 1] != g || shown[i + 2] != b)
          differing++;
      }
    Assert.Equal(0, differing);
    Shot(browser, "studio-render.png");

    // 2. Click a pixel on a ball: its ray tree, then the 3D view.
    ClickPixel(browser, 80, 60);
    Until(browser, () => browser.FindElement(By.Id("rays")).Text.Contains("Primary", StringComparison.Ordinal), "the ray tree");
    Assert.StartsWith("pixel [80, 60]", browser.FindElement(By.Id("rays")).Text);
    browser.FindElement(By.Id("show3d")).Click();
    Until(browser, () => browser.FindElement(By.Id("rays3dPane")).Displayed, "the 3D view");
    Shot(browser, "studio-probe-3d.png");
    browser.FindElement(By.Id("show3d")).Click();

    // 3. Edit the folder's script: a typo is marked at its line, the fix renders a new image.
    RenderIn(browser, studio.Server.Session, "Balls", 160, 120);
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1, "the editor");
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", "// Five balls\nRendering.Scenes.FiveBals(scene);\n");
    browser.FindElement(By.Id("save")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count > 0, "the diagnostics");
    IWebElement error = browser.FindElement(By.CssSelector("#diagnostics li"));
    Assert.Equal("2", error.GetAttribute("data-line"));
    Assert.Contains("CS0117", error.Text);
    Assert.Single(browser.FindElements(By.CssSelector("#editor .line-error")));
    Shot(browser, "studio-editor-error.png");

    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", "Rendering.Scenes.Flags(scene);\n");
    browser.FindElement(By.Id("save")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count == 0 &&
                         browser.FindElement(By.Id("stats")).Text.Length > 0 && !browser.FindElement(By.Id("stop")).Enabled &&
                         (string)Js(browser, "return document.getElementById('messages').textContent;")! == "", "the fixed script's image");
    Shot(browser, "studio-editor-fixed.png");
    File.WriteAllText(Path.Combine(studio.ScriptsFolder, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\n");
    browser.FindElement(By.Id("closeEditor")).Click();

    // 4. Path tracing, shown in passes of samples, then where its noise is.
    Js(browser, "document.getElementById('algorithm').value = 'path'; document.getElementById('spp').value = 16;");
    RenderIn(browser, studio.Server.Session, "Five balls", 320, 240);
    Assert.Contains("noise", browser.FindElement(By.Id("stats")).Text);
    Js(browser, "const k = document.getElementById('view-kind'); k.value = 'Noise'; k.dispatchEvent(new Event('change'));");
    Until(browser, () => (string?)Js(browser, "return document.getElementById('viewPng').getAttribute('href');") == "api/views/Noise.png" &&
                         (string)Js(browser, "return document.getElementById('messages').textContent;")! == "", "the noise view");
    System.Threading.Thread.Sleep(300);
    Shot(browser, "studio-noise.png");
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");
  }

  [SkippableFact]
  public void A_chosen_script_shows_its_own_values_and_a_value_the_user_changes_wins()
  {
    string path = Path.Combine(studio.ScriptsFolder, "OwnValues.cs");
    File.WriteAllText(path, """
      Rendering.Scenes.FiveBalls(scene);
      context[PropertyName.CTX_WIDTH] = 40;
      context[PropertyName.CTX_HEIGHT] = 30;
      context[PropertyName.CTX_SUPERSAMPLING] = 4;
      context[PropertyName.CTX_ALGORITHM] = new DistributedRayTracing();
      context[PropertyName.CTX_START_ANIM] = 0.0;
      context[PropertyName.CTX_END_ANIM] = 2.0;
      context[PropertyName.CTX_FPS] = 5.0;
      """);
    using ChromeDriver browser = Browser();
    OpenAndAdd(browser, path);
    Js(browser, "document.getElementById('algorithm').value = '';");   // the scene's choice, whatever an earlier test left

    string Value(string id) => (string)Js(browser, "return document.getElementById(arguments[0]).value;", id)!;
    bool Script(string id) => (bool)Js(browser, "return document.getElementById(arguments[0]).classList.contains('script');", id)!;
    void ScriptValuesShown()
    {
      Until(browser, () => Value("width") == "40" && Script("width"), "the script's size in the fields");
      Assert.Equal(("30", "4"), (Value("height"), Value("spp")));
      Assert.True(Script("height") && Script("spp"));
      Assert.Equal(("0", "2", "5"), (Value("animStart"), Value("animEnd"), Value("animFps")));
      Assert.Contains("DistributedRayTracing", browser.FindElement(By.CssSelector("#algorithm option")).Text);
    }
    ScriptValuesShown();

    // The user types a width: theirs wins (and the height shown with it), the script's supersampling stays.
    IWebElement width = browser.FindElement(By.Id("width"));
    width.Clear();
    width.SendKeys("24");
    Assert.False(Script("width") || Script("height"));
    Assert.True(Script("spp"));
    Js(browser, "document.getElementById('stats').textContent = '';");
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.StartsWith("24x30", StringComparison.Ordinal) &&
                         !browser.FindElement(By.Id("stop")).Enabled, "the render at the user's width");
    Assert.Contains("4 spp", browser.FindElement(By.Id("stats")).Text);
    Until(browser, () => browser.FindElement(By.Id("historyLabel")).Text.Contains("OwnValues", StringComparison.Ordinal), "the render in the history");

    // Another scene and back: the script's own values again.
    Js(browser, "const s = document.getElementById('scene'); s.value = 'Five balls'; s.dispatchEvent(new Event('change'));");
    Until(browser, () => !Script("width"), "Five balls's fields");
    Js(browser, "const s = document.getElementById('scene'); s.value = 'OwnValues'; s.dispatchEvent(new Event('change'));");
    ScriptValuesShown();
    Shot(browser, "studio-script-values.png", docs: true);
  }

  [SkippableFact]
  public void A_tab_whose_render_another_tab_replaced_says_so()
  {
    using ChromeDriver browser = Browser();
    string Messages() => browser.FindElement(By.Id("messages")).Text;
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    string first = browser.CurrentWindowHandle;
    RenderIn(browser, studio.Server.Session, "Five balls", 48, 36);
    Assert.DoesNotContain("Another tab", Messages());

    browser.SwitchTo().NewWindow(WindowType.Tab);
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the second tab's scene list");
    // A new tab has taken nothing from anyone: the first tab's image is on show, with no notice.
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.StartsWith("48x36", StringComparison.Ordinal), "the render on show in the new tab");
    Assert.DoesNotContain("Another tab", Messages());
    string second = browser.CurrentWindowHandle;
    RenderIn(browser, studio.Server.Session, "Five balls", 40, 30);
    Assert.DoesNotContain("Another tab", Messages());

    browser.SwitchTo().Window(first);
    Until(browser, () => Messages().Contains("Another tab or window of this studio started what is on show", StringComparison.Ordinal),
          "the first tab's notice");
    RenderIn(browser, studio.Server.Session, "Five balls", 48, 36);
    Until(browser, () => !Messages().Contains("Another tab", StringComparison.Ordinal), "the first tab's own render again");
    browser.SwitchTo().Window(second);
    Until(browser, () => Messages().Contains("Another tab", StringComparison.Ordinal), "the second tab's notice");
  }

  // The canvas's box on the page against the view's: (left, top, right, bottom) of each.
  static (double[] Image, double[] View) Boxes(IWebDriver browser)
  {
    var boxes = (IReadOnlyCollection<object>)Js(browser, """
      const b = r => [r.left, r.top, r.right, r.bottom];
      return [b(document.getElementById('canvas').getBoundingClientRect()), b(document.getElementById('view').getBoundingClientRect())];
      """)!;
    double[][] both = boxes.Select(o => ((IReadOnlyCollection<object>)o).Select(Convert.ToDouble).ToArray()).ToArray();
    return (both[0], both[1]);
  }

  /// <summary>The image inside the view and centred; as large as fits when <paramref name="enlarged"/>, else 1:1 (<paramref name="width"/> px wide).</summary>
  static void AssertFitted(IWebDriver browser, bool enlarged, int width)
  {
    (double[] image, double[] view) = Boxes(browser);
    Assert.True(image[0] >= view[0] - 0.5 && image[1] >= view[1] - 0.5 && image[2] <= view[2] + 0.5 && image[3] <= view[3] + 0.5,
                $"image [{string.Join(", ", image)}] outside the view [{string.Join(", ", view)}]");
    Assert.InRange(image[0] - view[0] - (view[2] - image[2]), -2.0, 2.0);
    Assert.InRange(image[1] - view[1] - (view[3] - image[3]), -2.0, 2.0);
    // As large as fits: 8 px of margin (view.js) from the view's sides or from its top and bottom.
    if (enlarged)
      Assert.True(Math.Min(image[0] - view[0], image[1] - view[1]) <= 9.0, $"image [{string.Join(", ", image)}] smaller than fits [{string.Join(", ", view)}]");
    else
      Assert.Equal(width, image[2] - image[0], 1);
  }

  [SkippableFact]
  public void Fit_shows_the_whole_image_centred_and_key_1_shows_it_1_to_1()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    RenderIn(browser, studio.Server.Session, "Five balls", 160, 120);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 160, "the image");

    // Zoomed and panned away first, so the fit has something to undo.
    IWebElement view = browser.FindElement(By.Id("view"));
    new Actions(browser).MoveToElement(view, 10, 10).ScrollByAmount(0, -300).Perform();
    browser.FindElement(By.Id("fit")).Click();
    // A small image is not blown up by default: fitted, it is 1:1, centred, drawn with square pixels.
    AssertFitted(browser, enlarged: false, 160);
    bool Smooth() => (bool)Js(browser, "return getComputedStyle(document.getElementById('canvas')).imageRendering === 'auto';")!;
    Assert.False(Smooth());

    // Asked for, fitting enlarges it, smoothly; zoomed with the wheel, its pixels are squares again.
    browser.FindElement(By.Id("enlarge")).Click();
    AssertFitted(browser, enlarged: true, 160);
    Assert.True(Boxes(browser).Image[2] - Boxes(browser).Image[0] > 160, "the small image is zoomed in to fit");
    Assert.True(Smooth());
    Js(browser, """
      const r = document.getElementById('view').getBoundingClientRect();
      document.getElementById('view').dispatchEvent(new WheelEvent('wheel',
        { deltaY: -100, clientX: (r.left + r.right) / 2, clientY: (r.top + r.bottom) / 2, bubbles: true, cancelable: true }));
      """);
    Assert.False(Smooth());
    browser.FindElement(By.Id("fit")).Click();

    // Key 1: one image pixel per screen pixel, about the view's centre; key F fits again.
    new Actions(browser).SendKeys("1").Perform();
    (double[] image, double[] box) = Boxes(browser);
    Assert.Equal(160.0, image[2] - image[0], 1);
    Assert.InRange((image[0] + image[2]) / 2 - (box[0] + box[2]) / 2, -2.0, 2.0);
    new Actions(browser).SendKeys("f").Perform();
    AssertFitted(browser, enlarged: true, 160);
    Shot(browser, "studio-fit.png");
    browser.FindElement(By.Id("enlarge")).Click();
    AssertFitted(browser, enlarged: false, 160);
  }

  [SkippableFact]
  public void The_probes_line_with_its_hash_is_readable_in_full()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    RenderIn(browser, studio.Server.Session, "Five balls", 160, 120);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 160, "the image");
    Js(browser, "window.dispatchEvent(new KeyboardEvent('keydown', { key: 'r' }));");
    IWebElement canvas = browser.FindElement(By.Id("canvas"));
    new Actions(browser).MoveToElement(canvas, 80 - canvas.Size.Width / 2, 60 - canvas.Size.Height / 2).Click().Perform();
    Until(browser, () => browser.FindElement(By.Id("rays")).Text.Contains("Primary", StringComparison.Ordinal), "the ray tree");
    IWebElement rays = browser.FindElement(By.Id("rays"));
    Assert.Contains("hash ", rays.Text);
    long scroll = (long)Js(browser, "return document.getElementById('rays').scrollWidth;")!;
    long client = (long)Js(browser, "return document.getElementById('rays').clientWidth;")!;
    Assert.True(scroll <= client, $"the ray tree is {scroll} px wide in {client} px");
  }

  [SkippableFact]
  public void The_page_follows_a_render_to_its_completion_by_pushed_events_without_asking_for_the_status()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    // Every request the page makes is listed by the browser (resource timing); room for all of them.
    Js(browser, "performance.setResourceTimingBufferSize(100000);");
    long Requests(string path) => (long)Js(browser,
      "return performance.getEntriesByType('resource').filter(e => new URL(e.name).pathname === arguments[0]).length;", path)!;
    long atLoad = Requests("/api/status");
    Assert.True(atLoad <= 1, $"{atLoad} status requests at load");

    // Path tracing in passes: previews and progress for a while, then the completion.
    Js(browser, "document.getElementById('algorithm').value = 'path'; document.getElementById('spp').value = 16;");
    RenderIn(browser, studio.Server.Session, "Five balls", 240, 180);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 240, "the image");
    Assert.Contains("noise", browser.FindElement(By.Id("stats")).Text);
    Assert.True(Requests("/api/image.png") >= 1);
    Until(browser, () => browser.FindElement(By.Id("historyLabel")).Text.Contains("Five balls", StringComparison.Ordinal), "the render in the history");
    Assert.Equal(atLoad, Requests("/api/status"));
    // One stream, this page's (an earlier test's closed browser's ends when the studio notices it gone).
    Until(browser, () => studio.Server.Session.EventStreams == 1, "one event stream");
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");
  }

  [SkippableFact]
  public void Probing_again_and_again_in_3d_holds_the_geometries_of_one_view()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    RenderIn(browser, studio.Server.Session, "Five balls", 160, 120);
    Js(browser, "window.dispatchEvent(new KeyboardEvent('keydown', { key: 'r' }));");
    IWebElement canvas = browser.FindElement(By.Id("canvas"));
    void ProbeAt(int x, int y)
    {
      Js(browser, "document.getElementById('rays').textContent = '';");
      new Actions(browser).MoveToElement(canvas, x - canvas.Size.Width / 2, y - canvas.Size.Height / 2).Click().Perform();
      Until(browser, () => browser.FindElement(By.Id("rays")).Text.StartsWith($"pixel [{x}, {y}]", StringComparison.Ordinal), "the ray tree");
    }
    string Memory() => (string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      import('./pane3d.js').then(m => done(JSON.stringify(m.memory())));
      """)!;
    ProbeAt(80, 60);
    browser.FindElement(By.Id("show3d")).Click();
    Until(browser, () => browser.FindElement(By.Id("rays3dPane")).Displayed, "the 3D view");
    Skip.If(Memory() == "null", "no WebGL in this browser");
    string first = Memory();
    foreach ((int x, int y) in new[] { (70, 50), (90, 64), (80, 60), (60, 70) })
      ProbeAt(x, y);
    System.Threading.Thread.Sleep(300);
    using JsonDocument a = JsonDocument.Parse(first), b = JsonDocument.Parse(Memory());
    // The scene's four geometries (one sphere shared by the five balls, the light's ball, the camera's lines and image
    // plane) and one per kind of line of the last probe (seven kinds at most), whatever came before.
    Assert.InRange(b.RootElement.GetProperty("geometries").GetInt32(), 1, 4 + 7);
    Assert.Equal(a.RootElement.GetProperty("programs").GetInt32(), b.RootElement.GetProperty("programs").GetInt32());
    browser.FindElement(By.Id("show3d")).Click();
    using JsonDocument closed = JsonDocument.Parse(Memory());
    Assert.Equal(0, closed.RootElement.GetProperty("geometries").GetInt32());
  }
}
