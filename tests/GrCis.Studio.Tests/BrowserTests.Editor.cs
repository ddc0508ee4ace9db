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

/// <summary>The script editor in the browser: a save that compiles another script, and changes made on disk by another editor.</summary>
public sealed partial class BrowserTests
{
  [SkippableFact]
  public void Saving_a_script_that_is_not_rendered_shows_compiling_then_its_errors()
  {
    string path = Path.Combine(studio.ScriptsFolder, "Edited.cs");
    File.WriteAllText(path, "Rendering.Scenes.FiveBalls(scene);\n");
    string marker = Path.Combine(studio.Folder, "browser-stuck").Replace("\\", "/", StringComparison.Ordinal);
    using ChromeDriver browser = Browser();
    OpenAndAdd(browser, path);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button of the added script");
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1, "the editor");
    string Phase() => browser.FindElement(By.Id("phase")).Text;
    void SaveText(string text)
    {
      Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", text);
      browser.FindElement(By.Id("save")).Click();
    }

    // A script that is slow to build: the page says so, and Stop ends it.
    SaveText(StuckScripts.WhileBuilding(marker));
    Until(browser, () => File.Exists(marker) && Phase() == "compiling the script…" && browser.FindElement(By.Id("stop")).Enabled,
          "the compiling state");
    browser.FindElement(By.Id("stop")).Click();
    Until(browser, () => Phase() == "" && !browser.FindElement(By.Id("stop")).Enabled, "idle after Stop");

    // A typo: marked at its line, though the script is not the one rendered.
    SaveText("// edited\n// here\nRendering.Scenes.FiveBals(scene);\n");
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count > 0, "the diagnostics");
    IWebElement error = browser.FindElement(By.CssSelector("#diagnostics li"));
    Assert.Equal("3", error.GetAttribute("data-line"));
    Assert.Contains("CS0117", error.Text);

    SaveText("Rendering.Scenes.FiveBalls(scene);\n");
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count == 0 &&
                         browser.FindElement(By.Id("messages")).Text == "Edited.cs compiles; Render shows it", "the fixed script compiled");
    browser.FindElement(By.Id("closeEditor")).Click();
  }

  [SkippableFact]
  public void A_change_on_disk_reloads_the_editor_or_asks_over_unsaved_edits()
  {
    string path = Path.Combine(studio.ScriptsFolder, "ChangedOnDisk.cs");
    File.WriteAllText(path, "Rendering.Scenes.FiveBalls(scene);\n");
    using ChromeDriver browser = Browser();
    OpenAndAdd(browser, path);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button of the added script");
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1, "the editor");
    string Text() => (string)Js(browser, "return document.querySelector('#editor .CodeMirror').CodeMirror.getValue();")!;
    bool Asking() => browser.FindElement(By.Id("sourceChanged")).Displayed;
    Until(browser, () => Text() == "Rendering.Scenes.FiveBalls(scene);\n", "the script's text");

    // No edits in the page: another editor's save shows at once.
    const string First = "// saved elsewhere\nRendering.Scenes.FiveBalls(scene);\n";
    File.WriteAllText(path, First);
    Until(browser, () => Text() == First, "the reloaded text");
    Assert.False(Asking());

    // Unsaved edits: the page asks, keeping them until the user chooses.
    const string Mine = "// mine\nRendering.Scenes.Flags(scene);\n", Second = "// saved elsewhere again\nRendering.Scenes.FiveBalls(scene);\n";
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", Mine);
    File.WriteAllText(path, Second);
    Until(browser, Asking, "the question about the change on disk");
    Assert.Equal(Mine, Text());
    Shot(browser, "studio-editor-changed-on-disk.png");
    browser.FindElement(By.Id("reloadSource")).Click();
    Until(browser, () => Text() == Second && !Asking(), "the disk's text after Reload");

    // Keep mine: the next save replaces the file knowingly.
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", Mine);
    File.WriteAllText(path, First);
    Until(browser, Asking, "the question again");
    browser.FindElement(By.Id("keepMine")).Click();
    browser.FindElement(By.Id("save")).Click();
    Until(browser, () => File.ReadAllText(path) == Mine, "the user's text saved");
    Assert.False(Asking());
    browser.FindElement(By.Id("closeEditor")).Click();
  }
}
