using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;

namespace GrCis.Studio.Tests;

/// <summary>A newcomer's first minute in the studio (issue 39), in a studio of its own that has rendered nothing yet.</summary>
public sealed partial class BrowserTests
{
  [SkippableFact]
  public async System.Threading.Tasks.Task A_fresh_page_selects_the_first_script_offers_no_download_yet_and_Enter_renders()
  {
    using ChromeDriver browser = Browser();
    DirectoryInfo folder = Directory.CreateTempSubdirectory("grcis-studio-newcomer-");
    try
    {
      File.WriteAllText(Path.Combine(folder.FullName, "Balls.cs"), "Rendering.Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_WIDTH] = 64; context[PropertyName.CTX_HEIGHT] = 48;\n");
      await using StudioServer server = await StudioServer.StartAsync(new StudioOptions { Paths = [folder.FullName] }, new List<string>());
      browser.Navigate().GoToUrl(server.Url);
      Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");

      // The folder's script is selected, shown by its file name in a group of scripts.
      Assert.Equal("Balls", (string)Js(browser, "return document.getElementById('scene').value;")!);
      Assert.Equal("Balls.cs", (string)Js(browser, "return document.getElementById('scene').selectedOptions[0].textContent;")!);
      Assert.Equal("Scripts", (string)Js(browser, "return document.getElementById('scene').selectedOptions[0].parentElement.label;")!);

      // Nothing rendered: the PNG and PFM links lead nowhere.
      foreach (string id in new[] { "png", "pfm" })
      {
        Assert.Null(browser.FindElement(By.Id(id)).GetAttribute("href"));
        Assert.Equal("true", browser.FindElement(By.Id(id)).GetAttribute("aria-disabled"));
      }

      // Enter in Parameters renders.
      browser.FindElement(By.Id("param")).SendKeys(Keys.Enter);
      Until(browser, () => browser.FindElement(By.Id("stats")).Text.StartsWith("64x48", StringComparison.Ordinal) &&
                           !browser.FindElement(By.Id("stop")).Enabled, "the render started by Enter", server.Session);
      Until(browser, () => browser.FindElement(By.Id("png")).GetAttribute("href") is { } href && href.EndsWith("api/image.png", StringComparison.Ordinal),
            "the PNG link after the render");
      Assert.Equal("false", browser.FindElement(By.Id("pfm")).GetAttribute("aria-disabled"));
    }
    finally
    {
      folder.Delete(recursive: true);
    }
  }
}
