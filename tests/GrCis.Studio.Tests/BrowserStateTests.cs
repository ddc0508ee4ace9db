using System;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using static GrCis.Studio.Tests.BrowserTests;

namespace GrCis.Studio.Tests;

/// <summary>
/// State the page must not misstate (issue 39): a page reloaded while a render runs shows that render's size and
/// samples per pixel (not the defaults, which the next Render would use), and a stopped render's bar stays where it
/// stopped, the phase saying "stopped", not 100 %.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class BrowserStateTests(ScriptsStudioFixture studio) : IClassFixture<ScriptsStudioFixture>
{
  [SkippableFact]
  public void A_reload_mid_render_shows_its_size_and_Stop_leaves_the_bar_where_it_stopped()
  {
    ChromeDriver browser = studio.Browser(1280, 720);
    void Load()
    {
      browser.Navigate().GoToUrl(studio.Server.Url);
      Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    }
    string Value(string id) => (string)Js(browser, "return document.getElementById(arguments[0]).value;", id)!;
    Load();
    // A long render: the size and samples typed in, as a user does (input events make them the user's).
    Js(browser, """
      const s = document.getElementById('scene'); s.value = 'Five balls'; s.dispatchEvent(new Event('change'));
      document.getElementById('algorithm').value = 'path';
      for (const [id, v] of [['width', 1600], ['height', 1200], ['spp', 64]]) {
        const f = document.getElementById(id); f.value = v; f.dispatchEvent(new Event('input'));
      }
      """);
    Until(browser, () => Value("width") == "1600", "the typed size");
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("phase")).Text == "rendering…", "the render running", studio.Server.Session);

    Load();
    Until(browser, () => Value("width") == "1600" && Value("height") == "1200", $"the running render's size (shown: {Value("width")}x{Value("height")})");
    Assert.Equal("64", Value("spp"));
    Assert.Equal("rendering…", browser.FindElement(By.Id("phase")).Text);

    browser.FindElement(By.Id("stop")).Click();
    Until(browser, () => browser.FindElement(By.Id("phase")).Text == "stopped", "the stopped render's end", studio.Server.Session);
    long shown = Convert.ToInt64(browser.FindElement(By.Id("progress")).GetAttribute("aria-valuenow"));
    Assert.True(shown < 100, $"the bar of a stopped render shows {shown} %");
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");
  }
}
