using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using OpenQA.Selenium.Interactions;
using static GrCis.Studio.Tests.BrowserLayoutTests;
using static GrCis.Studio.Tests.BrowserTests;

namespace GrCis.Studio.Tests;

/// <summary>
/// The editor with the repository's own scripts (issue 39), in headless chromium at a laptop's, a small laptop's, a
/// small window's and a desktop's size: the image keeps at least 320 px beside the editor, no control is cut off or
/// pushed out of the window, the page never scrolls sideways, an error reads as lines (not a column of characters),
/// the settings' select boxes show their whole text; the split between the editor and the image is dragged and kept;
/// axe-core finds no violation of any impact (load, render, editor, error, probe); an error thrown at a script's line
/// is marked when the editor opens after the failed render, and only in that script; the error goes when another scene
/// is chosen. One studio and one browser for the class.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed class BrowserEditorLayoutTests(ScriptsStudioFixture studio) : IClassFixture<ScriptsStudioFixture>
{
  /// <summary>Opens the page (again) and waits for the scene list.</summary>
  ChromeDriver Open(int width, int height)
  {
    ChromeDriver browser = studio.Browser(width, height);
    browser.Navigate().GoToUrl(studio.Server.Url);
    Until(browser, () => browser.FindElements(By.CssSelector("#scene option")).Count > 5, "the scene list");
    return browser;
  }

  /// <summary>Chooses the script whose file is <paramref name="file"/> (its label in the scene list); returns its scene name.</summary>
  static string Choose(ChromeDriver browser, string file) => (string)Js(browser, """
    const s = document.getElementById('scene'), o = [...s.options].find(o => o.textContent === arguments[0]);
    s.value = o.value; s.dispatchEvent(new Event('change')); return o.value;
    """, file)!;

  static void Render(ChromeDriver browser, StudioServer server, string file)
  {
    string scene = Choose(browser, file);
    Js(browser, "document.getElementById('algorithm').value = ''; document.getElementById('spp').value = 1;");
    RenderIn(browser, server.Session, scene, 200, 150);
  }

  static void OpenEditor(ChromeDriver browser)
  {
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1 && browser.FindElement(By.Id("editorPane")).Displayed,
          "the editor");
  }

  static string EditorText(ChromeDriver browser) => (string)Js(browser, "return document.querySelector('#editor .CodeMirror').CodeMirror.getValue();")!;

  /// <summary>
  /// The layout with the editor open: the image's view at least 320 px wide, left of the editor; every visible control
  /// whole inside the window and inside each ancestor that clips it (one that scrolls vertically may hide it below);
  /// nothing wider than the window; each visible select box wide enough for its chosen text.
  /// </summary>
  static void AssertEditorLayout(ChromeDriver browser, string state)
  {
    double[] view = Rect(browser, "view"), editor = Rect(browser, "editorPane");
    Assert.True(view[2] - view[0] >= 320, $"{state}: the image's view is {view[2] - view[0]:0} px wide, {Show(view)}, beside the editor {Show(editor)}");
    Assert.True(view[2] <= editor[0] + 0.5, $"{state}: the view {Show(view)} reaches under the editor {Show(editor)}");
    string problems = (string)Js(browser, """
      const W = innerWidth, H = innerHeight, out = [];
      const root = document.scrollingElement;
      if (root.scrollWidth > W) out.push(`the page is ${root.scrollWidth} px wide`);
      for (const e of document.querySelectorAll('button, a.button, select, input, [role=separator], summary')) {
        if (!e.checkVisibility() || e.closest('.CodeMirror')) continue;
        const r = e.getBoundingClientRect(), name = e.id || e.textContent.trim();
        if (r.left < -0.5 || r.right > W + 0.5 || r.top < -0.5 || r.bottom > H + 0.5) {
          // A control below the fold of a panel that scrolls is fine; one outside the window otherwise is not.
          if (!e.closest('aside') || r.left < -0.5 || r.right > W + 0.5) { out.push(`${name} outside the window`); continue; }
        }
        for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
          const cs = getComputedStyle(a);
          if (cs.overflowX === 'visible' && cs.overflowY === 'visible') continue;
          const b = a.getBoundingClientRect(), scrollsY = cs.overflowY === 'auto' || cs.overflowY === 'scroll';
          if (r.left < b.left - 0.5 || r.right > b.right + 0.5 || !scrollsY && (r.top < b.top - 0.5 || r.bottom > b.bottom + 0.5))
            out.push(`${name} cut by ${a.id || a.tagName.toLowerCase()}`);
        }
      }
      // A select box shows its chosen text whole: the text's width within the box less its padding and arrow.
      const measure = document.createElement('canvas').getContext('2d');
      for (const s of document.querySelectorAll('select')) {
        if (!s.checkVisibility() || !s.selectedOptions[0]) continue;
        const cs = getComputedStyle(s);
        measure.font = `${cs.fontWeight} ${cs.fontSize} ${cs.fontFamily}`;
        const text = measure.measureText(s.selectedOptions[0].textContent).width;
        const room = s.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) - 18;
        if (text > room) out.push(`${s.id}: "${s.selectedOptions[0].textContent}" is ${text.toFixed(0)} px in ${room.toFixed(0)} px`);
      }
      return out.join('; ');
      """)!;
    Assert.True(problems.Length == 0, $"{state}: {problems}");
  }

  [SkippableTheory]
  [InlineData(1366, 768)]
  [InlineData(1280, 720)]
  [InlineData(1024, 700)]
  [InlineData(1920, 1080)]
  public void The_longest_script_in_the_editor_leaves_the_image_room_and_every_control_in_the_window(int width, int height)
  {
    string size = $"{width}x{height}";
    bool full = width == 1366;   // every state checked with axe-core at one size; the editor's at every size
    ChromeDriver browser = Open(width, height);
    Js(browser, "localStorage.clear();");   // the default split, whatever ran before
    if (full)
      AssertAccessible(browser, $"{size}, the page as loaded", anyImpact: true);

    // The longest script, rendered (its picture as a student sees it), then in the editor.
    string longest = studio.Longest;
    Render(browser, studio.Server, longest);
    if (full)
    {
      AssertAccessible(browser, $"{size}, a finished render", anyImpact: true);
      ClickPixel(browser, 100, 75);
      Until(browser, () => browser.FindElement(By.Id("rays")).Text.StartsWith("pixel [100, 75]", StringComparison.Ordinal), "the ray tree");
      AssertAccessible(browser, $"{size}, a probed pixel", anyImpact: true);
    }
    OpenEditor(browser);
    Until(browser, () => EditorText(browser) == File.ReadAllText(Path.Combine(studio.Folder, longest)).ReplaceLineEndings("\n"), "the script's text");
    Shot(browser, $"studio-editor-script-{size}.png", docs: full);
    AssertEditorLayout(browser, $"{size}, {longest} in the editor");
    AssertImageFittedAndVisible(browser, width, height);
    AssertAccessible(browser, $"{size}, {longest} in the editor", anyImpact: true);

    // A runtime error: its message above the image, in lines as wide as the view, not a column of characters.
    string failing = Choose(browser, ScriptsStudioFixture.Failing + ".cs");
    Js(browser, "document.getElementById('stats').textContent = '';");
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("messageBox")).Displayed &&
                         browser.FindElement(By.Id("messages")).Text.Contains("NullReferenceException", StringComparison.Ordinal) &&
                         !browser.FindElement(By.Id("stop")).Enabled, $"the error of {failing}", studio.Server.Session);
    Shot(browser, $"studio-editor-script-error-{size}.png");
    AssertEditorLayout(browser, $"{size}, an error beside the editor");
    double[] box = Rect(browser, "messages");
    double line = Convert.ToDouble(Js(browser, "return parseFloat(getComputedStyle(document.getElementById('messages')).lineHeight);"));
    Assert.True(box[2] - box[0] >= 250, $"{size}: the error's text is {box[2] - box[0]:0} px wide");
    Assert.True(box[3] - box[1] <= 6 * line, $"{size}: the error takes {(box[3] - box[1]) / line:0} lines");
    if (full)
      AssertAccessible(browser, $"{size}, an error beside the editor", anyImpact: true);
    // The error is at line 3 of the failing script, not of the one in the editor: nothing marked there.
    Assert.Empty(browser.FindElements(By.CssSelector("#editor .line-error")));
    Assert.Empty(browser.FindElements(By.CssSelector("#diagnostics li")));
    // Another scene chosen: the error was the failing script's, and goes.
    Choose(browser, longest);
    Until(browser, () => !browser.FindElement(By.Id("messageBox")).Displayed, "no error once another scene is chosen");

    // Every script of the repository in the editor: none widens it.
    if (width == 1024)
      foreach (string script in studio.Scripts)
      {
        Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", File.ReadAllText(Path.Combine(studio.Folder, script)));
        AssertEditorLayout(browser, $"{size}, {script} in the editor");
      }
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.markClean();");
    browser.FindElement(By.Id("closeEditor")).Click();
  }

  [SkippableFact]
  public void The_split_between_image_and_editor_is_dragged_kept_and_leaves_the_image_its_room()
  {
    ChromeDriver browser = Open(1366, 768);
    Js(browser, "localStorage.clear();");
    Choose(browser, studio.Longest);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button");
    OpenEditor(browser);
    double Editor() => Rect(browser, "editorPane")[2] - Rect(browser, "editorPane")[0];
    IWebElement split = browser.FindElement(By.Id("editorSplit"));
    double before = Editor();

    // Dragged 150 px left: the editor is 150 px wider, and so it stays after a reload.
    new Actions(browser).ClickAndHold(split).MoveByOffset(-150, 0).Release().Perform();
    Until(browser, () => Math.Abs(Editor() - (before + 150)) <= 2, $"the editor 150 px wider than {before:0} px (now {Editor():0})");
    double dragged = Editor();
    Assert.Equal(Math.Round(dragged), Convert.ToDouble(Js(browser, "return Number(localStorage.getItem('grcis-editor-width'));")), 1.0);
    Open(1366, 768);
    Choose(browser, studio.Longest);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button after the reload");
    OpenEditor(browser);
    Assert.Equal(dragged, Editor(), 1.0);

    // Dragged as far as it goes, either way: the image keeps 320 px, the editor 240 px.
    // (Within the window: WebDriver moves the pointer only there.)
    double SplitX() => (Rect(browser, "editorSplit")[0] + Rect(browser, "editorSplit")[2]) / 2;
    split = browser.FindElement(By.Id("editorSplit"));
    new Actions(browser).ClickAndHold(split).MoveByOffset(-(int)SplitX() + 5, 0).Release().Perform();
    Until(browser, () => Rect(browser, "view")[2] - Rect(browser, "view")[0] < 330, "the editor at its widest");
    double[] view = Rect(browser, "view");
    Assert.InRange(view[2] - view[0], 319.5, 330.0);
    AssertEditorLayout(browser, "the editor at its widest");
    split = browser.FindElement(By.Id("editorSplit"));
    new Actions(browser).ClickAndHold(split).MoveByOffset(1366 - 5 - (int)SplitX(), 0).Release().Perform();
    Until(browser, () => Editor() < 250, "the editor at its narrowest");
    Assert.InRange(Editor(), 239.5, 250.0);
    AssertEditorLayout(browser, "the editor at its narrowest");

    // The keys: Left widens the editor a step; a double click goes back to the default share.
    double narrow = Editor();
    split.SendKeys(Keys.ArrowLeft);
    Until(browser, () => Editor() > narrow + 10, "the editor a step wider");
    Assert.Equal(Math.Round(Editor()), Convert.ToDouble(Js(browser, "return Number(localStorage.getItem('grcis-editor-width'));")), 1.0);
    new Actions(browser).DoubleClick(split).Perform();
    Until(browser, () => Math.Abs(Editor() - before) <= 1, "the default width again");
    Assert.Null(Js(browser, "return localStorage.getItem('grcis-editor-width');"));
    browser.FindElement(By.Id("closeEditor")).Click();
  }

  [SkippableFact]
  public void An_error_thrown_at_a_line_is_marked_when_the_editor_opens_after_the_render()
  {
    ChromeDriver browser = Open(1280, 720);
    // A fresh page: the editor has never been opened, so nothing could be marked while the render failed.
    Choose(browser, ScriptsStudioFixture.Failing + ".cs");
    Js(browser, "document.getElementById('algorithm').value = '';");
    browser.FindElement(By.Id("render")).Click();
    Until(browser, () => browser.FindElement(By.Id("messages")).Text.Contains("NullReferenceException", StringComparison.Ordinal) &&
                         !browser.FindElement(By.Id("stop")).Enabled, "the runtime error", studio.Server.Session);
    OpenEditor(browser);
    Until(browser, () => browser.FindElements(By.CssSelector("#diagnostics li")).Count == 1, "the error listed under the editor");
    Assert.Equal("3", browser.FindElement(By.CssSelector("#diagnostics li")).GetAttribute("data-line"));
    Assert.Contains("NullReferenceException", browser.FindElement(By.CssSelector("#diagnostics li")).Text);
    // Its line marked in the code (CodeMirror's line 3 is the third .CodeMirror-line).
    Assert.Equal(2L, Js(browser, """
      const lines = [...document.querySelectorAll('#editor .CodeMirror-code > div')];
      return lines.findIndex(l => l.classList.contains('line-error') || l.querySelector('.line-error'));
      """));
    browser.FindElement(By.Id("closeEditor")).Click();
  }
}
