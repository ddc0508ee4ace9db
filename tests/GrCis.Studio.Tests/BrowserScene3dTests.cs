using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using Rendering.Imaging;
using Xunit.Abstractions;
using static GrCis.Studio.Tests.BrowserTests;

namespace GrCis.Studio.Tests;

/// <summary>
/// The scene in 3D (issue 42) in a real browser: the repository's scripts drawn as their solids, lights and camera; the
/// layers' checkboxes remembered across a reload; and "View from camera" lining the spheres up with the render.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed partial class BrowserScene3dTests(ScriptsStudioFixture studio, ITestOutputHelper output) : IClassFixture<ScriptsStudioFixture>
{
  ChromeDriver Load()
  {
    ChromeDriver browser = studio.Browser(1280, 720);
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Skip.IfNot((bool)Js(browser, "return !!document.createElement('canvas').getContext('webgl');")!, "no WebGL in this browser");
    return browser;
  }

  /// <summary>Renders the script <paramref name="file"/> at the size typed in (so it wins over the script's), one sample per pixel.</summary>
  void Render(ChromeDriver browser, string file, int width, int height)
  {
    // Chosen as the list's change event chooses it, and waited for until the script's own values are in the fields (a
    // fixed pause lost that race on a loaded machine): the typed ones then win.
    ((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      const s = document.getElementById('scene'), o = [...s.options].find(o => o.textContent === arguments[0]);
      s.value = o.value;
      import('./settings.js').then(m => m.sceneChanged(new Event('change'))).then(() => done());
      """, file);
    Js(browser, """
      document.getElementById('algorithm').value = '';
      for (const [id, v] of [['width', arguments[0]], ['height', arguments[1]], ['spp', 1]]) {
        const f = document.getElementById(id); f.value = v; f.dispatchEvent(new Event('input'));
      }
      document.getElementById('stats').textContent = '';
      """, width, height);
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("stats")).Text.StartsWith($"{width}x{height}", StringComparison.Ordinal) &&
                         !browser.FindElement(By.Id("stop")).Enabled, $"the render of {file}", studio.Server.Session);
  }

  /// <summary>Opens the 3D pane afresh and waits until it shows the scene; returns what its layers hold.</summary>
  static Dictionary<string, int> Open3d(ChromeDriver browser)
  {
    Js(browser, "const p = document.getElementById('rays3dPane'); if (!p.hidden) document.getElementById('show3d').click(); delete p.dataset.surfaces;");
    browser.FindElement(By.Id("show3d")).Click();
    Until(browser, () => Js(browser, "return document.getElementById('rays3dPane').dataset.surfaces;") != null, "the scene in 3D");
    var data = (IReadOnlyDictionary<string, object>)Js(browser, "return Object.assign({}, document.getElementById('rays3dPane').dataset);")!;
    // The counts (the other attributes name the scene, the highlighted part, what a pick found).
    return data.Where(d => int.TryParse(Convert.ToString(d.Value), out _)).ToDictionary(d => d.Key, d => Convert.ToInt32(d.Value));
  }

  [SkippableTheory]
  [InlineData("FiveBalls.cs", 5, 1, 0)]
  [InlineData("TwoSpheres.cs", 3, 1, 0)]
  [InlineData("MeshVase.cs", 2, 1, 0)]
  // Floor, three walls, the ceiling in four pieces around the light, two spheres; its light is the emissive panel.
  [InlineData("CornellBox.cs", 10, 0, 1)]
  public void A_scripts_solids_lights_and_camera_are_in_the_3d_view(string file, int surfaces, int lights, int emitters)
  {
    ChromeDriver browser = Load();
    Render(browser, file, 64, 48);
    Dictionary<string, int> shown = Open3d(browser);
    output.WriteLine($"{file}: {string.Join(", ", shown.Select(d => $"{d.Key} {d.Value}"))}");
    Assert.Equal(surfaces, shown["surfaces"]);
    Assert.Equal(0, shown["boxSolids"]);
    Assert.Equal(lights, shown["lights"]);
    Assert.Equal(emitters, shown["emitters"]);
    Assert.Equal(1, shown["cameras"]);
    // The same as the studio's tessellation of the render says.
    using HttpClient client = StudioFixture.ClientOf(studio.Server);
    JsonElement scene = client.GetFromJsonAsync<JsonElement>("/api/scene/tessellation").GetAwaiter().GetResult();
    Assert.Equal(scene.GetProperty("parts").GetArrayLength(), shown["surfaces"] + shown["boxSolids"] + shown["emitters"]);
    Assert.Equal(scene.GetProperty("lights").GetArrayLength(), shown["lights"]);
  }

  [SkippableFact]
  public void A_probed_pixels_rays_are_drawn_among_the_scene_and_the_view_from_the_camera_is_the_renders()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Render(browser, "TwoSpheres.cs", 320, 240);
    ClickPixel(browser, 150, 130);
    Until(browser, () => browser.FindElement(By.Id("rays")).Text.Contains("Primary Sphere", StringComparison.Ordinal), "the glass ball's ray tree");
    Dictionary<string, int> shown = Open3d(browser);
    Assert.True(shown["raySegments"] >= 3, $"{shown["raySegments"]} ray segments");
    System.Threading.Thread.Sleep(200);
    Shot(browser, "studio-3d.png", docs: true);
    browser.FindElement(By.Id("fromCamera")).Click();
    Assert.Equal("true", browser.FindElement(By.Id("fromCamera")).GetAttribute("aria-pressed"));
    System.Threading.Thread.Sleep(200);
    Shot(browser, "studio-3d-camera.png", docs: true);
    browser.FindElement(By.Id("show3d")).Click();
  }

  [SkippableFact]
  public void A_new_render_replaces_the_scene_in_the_open_pane_and_gives_the_old_ones_gpu_memory_back()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    string Scene() => (string)Js(browser, "return document.getElementById('rays3dPane').dataset.scene;")!;
    JsonElement Memory() => JsonDocument.Parse((string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      import('./pane3d.js').then(m => done(JSON.stringify(m.memory())));
      """)!).RootElement;
    Render(browser, "FiveBalls.cs", 64, 48);
    Open3d(browser);
    int first = Memory().GetProperty("geometries").GetInt32();
    foreach (string file in new[] { "CornellBox.cs", "TwoSpheres.cs", "FiveBalls.cs" })
    {
      string before = Scene();
      Render(browser, file, 64, 48);
      Until(browser, () => Scene() != before, $"{file}'s scene in the open pane");
    }
    System.Threading.Thread.Sleep(200);
    // Five balls again: as many geometries on the GPU as the first time, not those of the scenes in between too.
    Assert.Equal(5, Convert.ToInt32(Js(browser, "return document.getElementById('rays3dPane').dataset.surfaces;")));
    Assert.Equal(first, Memory().GetProperty("geometries").GetInt32());
    browser.FindElement(By.Id("show3d")).Click();
    Assert.Equal(0, Memory().GetProperty("geometries").GetInt32());
  }

  [SkippableFact]
  public void The_layers_checkboxes_hide_layers_and_are_remembered_across_a_reload()
  {
    ChromeDriver browser = Load();
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Render(browser, "FiveBalls.cs", 64, 48);
    Open3d(browser);
    bool Checked(string layer) => (bool)Js(browser, $"return document.querySelector('#layers3d [data-layer={layer}]').checked;")!;
    Assert.True(Checked("surfaces") && Checked("lights") && Checked("camera") && Checked("rays"));
    Assert.False(Checked("boxes"));
    browser.FindElement(By.CssSelector("#layers3d [data-layer=lights]")).Click();
    browser.FindElement(By.CssSelector("#layers3d [data-layer=boxes]")).Click();
    string Visible() => (string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      import('./pane3d.js').then(m => done(m.visibleLayers().join(',')));
      """)!;
    Assert.Equal("surfaces,boxes,camera,rays", Visible());

    browser.Navigate().Refresh();
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Until(browser, () => browser.FindElement(By.Id("show3d")).Displayed, "the 3D button");
    Open3d(browser);
    Assert.False(Checked("lights"));
    Assert.True(Checked("boxes"));
    Assert.Equal("surfaces,boxes,camera,rays", Visible());
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
  }

  [SkippableFact]
  public void Viewed_from_the_camera_the_spheres_silhouettes_are_where_the_render_has_them()
  {
    const int width = 320, height = 240;
    ChromeDriver browser = Load();
    Js(browser, "localStorage.setItem('grcis-3d-layers', JSON.stringify({ surfaces: true, boxes: false, lights: false, camera: false, rays: false }));");
    browser.Navigate().Refresh();
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Render(browser, "FiveBalls.cs", width, height);
    Open3d(browser);
    browser.FindElement(By.Id("fromCamera")).Click();
    Shot(browser, "studio-3d-from-camera.png");
    string url = (string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      import('./pane3d.js').then(m => done(m.snapshot()));
      """)!;
    Js(browser, "localStorage.removeItem('grcis-3d-layers');");
    Rgb8Image view = Decode(Convert.FromBase64String(url[(url.IndexOf(',') + 1)..]), "view-from-camera.png");
    using HttpClient client = StudioFixture.ClientOf(studio.Server);
    Rgb8Image render = Decode(client.GetByteArrayAsync("/api/image.png").GetAwaiter().GetResult(), "render.png");
    Assert.Equal((width, height), (view.Width, view.Height));

    // The solids' pixels: those unlike the background (the render's corner; the view's clear colour #111).
    bool[,] inRender = Mask(render, render.GetPixel(0, 0)), inView = Mask(view, (17, 17, 17));
    var a = Silhouettes(inRender);
    var b = Silhouettes(inView);
    Assert.Equal(5, a.Count);
    Assert.Equal(5, b.Count);
    int offset = a.Zip(b, (p, q) => new[] { p.X0 - q.X0, p.X1 - q.X1, p.Y0 - q.Y0, p.Y1 - q.Y1 }.Max(Math.Abs)).Max();
    int both = 0, either = 0;
    for (int y = 0; y < height; y++)
      for (int x = 0; x < width; x++)
      {
        both += inRender[x, y] && inView[x, y] ? 1 : 0;
        either += inRender[x, y] || inView[x, y] ? 1 : 0;
      }
    output.WriteLine($"silhouettes' boxes differ by at most {offset} px; the pixel sets overlap {100.0 * both / either:F2} % (intersection over union)");
    Assert.InRange(offset, 0, 2);
    Assert.True(both > 0.95 * either, $"intersection over union {100.0 * both / either:F2} %");
  }

  static Rgb8Image Decode(byte[] png, string name)
  {
    string dir = Path.Combine(AppContext.BaseDirectory, "screenshots");
    Directory.CreateDirectory(dir);
    string path = Path.Combine(dir, name);
    File.WriteAllBytes(path, png);
    return ImageFile.LoadRgb8(path);
  }

  static bool[,] Mask(Rgb8Image image, (byte R, byte G, byte B) background)
  {
    var mask = new bool[image.Width, image.Height];
    for (int y = 0; y < image.Height; y++)
      for (int x = 0; x < image.Width; x++)
      {
        (byte r, byte g, byte b) = image.GetPixel(x, y);
        mask[x, y] = Math.Max(Math.Abs(r - background.R), Math.Max(Math.Abs(g - background.G), Math.Abs(b - background.B))) > 24;
      }
    return mask;
  }

  /// <summary>The boxes of the runs of columns that hold solid pixels, left to right (the five balls stand apart in a row).</summary>
  static List<(int X0, int X1, int Y0, int Y1)> Silhouettes(bool[,] mask)
  {
    var found = new List<(int X0, int X1, int Y0, int Y1)>();
    int w = mask.GetLength(0), h = mask.GetLength(1);
    (int X0, int X1, int Y0, int Y1)? run = null;
    for (int x = 0; x <= w; x++)
    {
      int y0 = int.MaxValue, y1 = -1;
      for (int y = 0; x < w && y < h; y++)
        if (mask[x, y])
        {
          y0 = Math.Min(y0, y);
          y1 = y;
        }
      if (y1 >= 0)
        run = run is { } r ? (r.X0, x, Math.Min(r.Y0, y0), Math.Max(r.Y1, y1)) : (x, x, y0, y1);
      else if (run is { } done)
      {
        found.Add(done);
        run = null;
      }
    }
    return found;
  }
}
