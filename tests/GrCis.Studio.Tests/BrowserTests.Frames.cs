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

/// <summary>Frames and kept renders in the browser: the animation's Play and frame PNG, the A/B comparison of two renders.</summary>
public sealed partial class BrowserTests
{
  [SkippableFact]
  public void Play_steps_through_the_frames_and_the_frame_link_is_the_shown_frame()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    Js(browser, "const s = document.getElementById('scene'); s.value = 'Balls'; s.dispatchEvent(new Event('change'));");
    browser.FindElement(By.CssSelector("#animationPanel summary")).Click();   // the panel opens as a user opens it
    Js(browser, """
      const set = (id, v) => { const f = document.getElementById(id); f.value = v; f.dispatchEvent(new Event('change')); };
      set('width', 32); set('height', 24); set('animStart', 0); set('animEnd', 0.5); set('animFps', 10); set('animFolder', '');
      """);
    browser.FindElement(By.Id("animRender")).Click();
    Until(browser, () => System.Text.RegularExpressions.Regex.IsMatch(browser.FindElement(By.Id("animStatus")).Text, @"^(\d+)/\1 frames") &&
                         !browser.FindElement(By.Id("animStop")).Enabled, "the frames");
    int last = int.Parse(browser.FindElement(By.Id("animStatus")).Text.Split('/')[0], System.Globalization.CultureInfo.InvariantCulture) - 1;
    Assert.True(last >= 4, browser.FindElement(By.Id("animStatus")).Text);
    IWebElement play = browser.FindElement(By.Id("animPlay"));
    Until(browser, () => play.Enabled, "the Play button");
    string Shown() => browser.FindElement(By.Id("animFrame")).GetAttribute("data-frame") ?? "";
    Until(browser, () => Shown() == last.ToString(System.Globalization.CultureInfo.InvariantCulture), "the last frame on show");
    // The status bar and History describe the frame on show, not the still render before it.
    Assert.StartsWith($"animation frame {last + 1}/{last + 1}", browser.FindElement(By.Id("stats")).Text);
    Assert.Contains("not kept in History", browser.FindElement(By.Id("historyLabel")).Text);

    // Play: the frames go round (from the last to the first and on).
    play.Click();
    Assert.Equal("Pause", play.Text);
    var seen = new HashSet<string>();
    Until(browser, () => { seen.Add(Shown()); return seen.Count >= 3; }, "three different frames while playing");
    play.Click();
    Assert.Equal("Play", play.Text);
    System.Threading.Thread.Sleep(300);   // a step already under way ends
    string k = Shown();
    System.Threading.Thread.Sleep(400);
    Assert.Equal(k, Shown());   // paused: it stays

    // The link's PNG is the frame on show: the served frame's bytes, and the pixels the canvas shows.
    IWebElement link = browser.FindElement(By.Id("framePng"));
    Assert.True(link.Displayed);
    string linked = (string)((IJavaScriptExecutor)browser).ExecuteAsyncScript("""
      const done = arguments[arguments.length - 1];
      fetch(document.getElementById('framePng').href).then(r => r.arrayBuffer()).then(b => {
        let s = ''; for (const x of new Uint8Array(b)) s += String.fromCharCode(x); done(btoa(s)); });
      """)!;
    byte[] bytes = Convert.FromBase64String(linked);
    byte[] frame = studio.Client.GetByteArrayAsync($"/api/animation/frame/{k}.png").GetAwaiter().GetResult();
    Assert.Equal(frame, bytes);
    string png = Path.Combine(studio.Folder, "shown-frame.png");
    File.WriteAllBytes(png, bytes);
    Rgb8Image expected = ImageFile.LoadRgb8(png);
    var shown = ((IReadOnlyCollection<object>)Js(browser,
      "const c = document.getElementById('canvas'); return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);")!)
      .Select(Convert.ToByte).ToArray();
    Assert.Equal(4 * 32 * 24, shown.Length);
    for (int y = 0; y < 24; y++)
      for (int x = 0; x < 32; x++)
      {
        (byte r, byte g, byte b) = expected.GetPixel(x, y);
        int i = 4 * (y * 32 + x);
        Assert.True(shown[i] == r && shown[i + 1] == g && shown[i + 2] == b, $"pixel [{x}, {y}] of frame {k}");
      }
  }

  static byte[] CanvasPixels(IWebDriver browser, string id) => ((IReadOnlyCollection<object>)Js(browser,
    "const c = document.getElementById(arguments[0]); return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);", id)!)
    .Select(Convert.ToByte).ToArray();

  [SkippableFact]
  public void A_kept_render_is_compared_with_the_one_on_show_left_and_right_of_the_split()
  {
    using ChromeDriver browser = Browser();
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    RenderIn(browser, studio.Server.Session, "Five balls", 64, 48);
    Until(browser, () => (long)Js(browser, "return document.getElementById('canvas').width;")! == 64, "the first image");
    byte[] first = CanvasPixels(browser, "canvas");
    RenderIn(browser, studio.Server.Session, "Flags", 64, 48);
    Until(browser, () => browser.FindElement(By.Id("historyLabel")).Text.Contains("Flags", StringComparison.Ordinal) &&
                         CanvasPixels(browser, "canvas") is var shown && !shown.SequenceEqual(first), "the second image");
    byte[] second = CanvasPixels(browser, "canvas");

    // B: the render before the one on show, drawn over it, its pixels the first render's.
    long options = (long)Js(browser, "return document.getElementById('abWith').options.length;")!;
    string b = (options - 3).ToString(System.Globalization.CultureInfo.InvariantCulture);
    Js(browser, "const s = document.getElementById('abWith'); s.value = arguments[0]; s.dispatchEvent(new Event('change'));", b);
    Assert.Contains("Five balls", (string)Js(browser, "return document.getElementById('abWith').selectedOptions[0].textContent;")!);
    Until(browser, () => (string?)Js(browser, "return document.getElementById('canvasB').dataset.item;") == b, "the B image");
    Assert.Equal(first, CanvasPixels(browser, "canvasB"));
    Assert.True(browser.FindElement(By.Id("abSplit")).Displayed);

    // On screen (fitted): left of the split A, right of it B; with the split at 100 % all A.
    new Actions(browser).SendKeys("f").Perform();
    int row = Enumerable.Range(0, 48).First(y => Differs(y, 8) && Differs(y, 56));
    bool Differs(int y, int x) => Enumerable.Range(0, 3).Any(c => Math.Abs(first[4 * (y * 64 + x) + c] - second[4 * (y * 64 + x) + c]) > 16);
    (byte, byte, byte) Pixel(byte[] image, int x) => (image[4 * (row * 64 + x)], image[4 * (row * 64 + x) + 1], image[4 * (row * 64 + x) + 2]);
    Assert.Equal((Pixel(second, 8), Pixel(first, 56)), (OnScreen(8), OnScreen(56)));
    Shot(browser, "studio-ab.png");
    Js(browser, "const s = document.getElementById('abSplit'); s.value = 100; s.dispatchEvent(new Event('input'));");
    Assert.Equal((Pixel(second, 8), Pixel(second, 56)), (OnScreen(8), OnScreen(56)));

    (byte, byte, byte) OnScreen(int x)
    {
      var box = ((IReadOnlyCollection<object>)Js(browser, "const r = document.getElementById('canvas').getBoundingClientRect(); return [r.left, r.top, r.width];")!)
        .Select(Convert.ToDouble).ToArray();
      string shot = Path.Combine(studio.Folder, "ab-shot.png");
      File.WriteAllBytes(shot, browser.GetScreenshot().AsByteArray);
      Rgb8Image screen = ImageFile.LoadRgb8(shot);
      double scale = box[2] / 64;
      return screen.GetPixel((int)(box[0] + (x + 0.5) * scale), (int)(box[1] + (row + 0.5) * scale));
    }
  }
}
