using System;
using System.IO;
using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;
using OpenQA.Selenium.Interactions;

namespace GrCis.Studio.Tests;

/// <summary>The editor's language services as a student meets them: completion, signature help, hover, errors while typing.</summary>
public sealed partial class BrowserTests
{
  [SkippableFact]
  public void The_editor_completes_shows_signatures_and_docs_and_marks_errors_without_saving()
  {
    const string saved = "Rendering.Scenes.FiveBalls(scene);\n";
    string path = Path.Combine(studio.ScriptsFolder, "Assisted.cs");
    File.WriteAllText(path, saved);
    using ChromeDriver browser = Browser();
    OpenAndAdd(browser, path);
    Until(browser, () => browser.FindElement(By.Id("edit")).Displayed, "the Edit button of the added script");
    // The script's own picture beside the editor, as a student sees it (and the screenshots in docs/studio.md show).
    Js(browser, "document.getElementById('algorithm').value = '';");
    RenderIn(browser, studio.Server.Session, "Assisted", 320, 240);
    browser.FindElement(By.Id("edit")).Click();
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror")).Count == 1, "the editor");
    IWebElement input = browser.FindElement(By.CssSelector("#editor .CodeMirror-code[contenteditable]"));
    void TypeAtEnd(string keys)
    {
      Js(browser, "const cm = document.querySelector('#editor .CodeMirror').CodeMirror; cm.focus(); cm.setCursor(cm.lineCount(), 0);");
      input.SendKeys(keys);
    }
    bool Shown(string id) => (bool)Js(browser, "const e = document.getElementById(arguments[0]); return !!e && !e.hidden;", id)!;
    string Text(string id) => (string)Js(browser, "return document.getElementById(arguments[0])?.textContent ?? '';", id)!;

    // "scene." lists the scene's members; the selected one comes with its signature.
    TypeAtEnd("scene.");
    Until(browser, () => browser.FindElements(By.XPath("//ul[contains(@class,'CodeMirror-hints')]/li[starts-with(., 'Intersectable')]")).Count == 1,
          "the scene's members in the completion list");
    Until(browser, () => Shown("assistDoc") && Text("assistDoc").Length > 0, "the selected entry's description");
    Shot(browser, "studio-editor-completion.png", docs: true);
    input.SendKeys(Keys.Escape);
    Until(browser, () => browser.FindElements(By.CssSelector(".CodeMirror-hints")).Count == 0, "the list closed");

    // A call's parentheses show the constructor's signature.
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", saved);
    TypeAtEnd("var m = new PhongMaterial(");
    Until(browser, () => Shown("assistSignature") && Text("assistSignature").Contains("PhongMaterial(", StringComparison.Ordinal), "the signature");
    Shot(browser, "studio-editor-signature.png", docs: true);
    input.SendKeys(Keys.Escape);

    // Hovering the type name shows its doc comment.
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", "PhongMaterial m = null;\n" + saved);
    IWebElement name = browser.FindElement(By.XPath("//div[@id='editor']//span[text()='PhongMaterial']"));
    new Actions(browser).MoveToElement(name).Perform();
    Until(browser, () => Shown("assistHover") && Text("assistHover").Contains("Phong material", StringComparison.Ordinal), "the doc comment on hover");

    // A type error is marked while typing, nothing saved.
    Js(browser, "document.querySelector('#editor .CodeMirror').CodeMirror.setValue(arguments[0]);", saved);
    TypeAtEnd("int count = \"many\";");
    Until(browser, () => browser.FindElements(By.CssSelector("#editor .CodeMirror-lint-mark-error")).Count > 0 &&
                         browser.FindElements(By.CssSelector("#editor .CodeMirror-lint-marker-error")).Count > 0, "the error marked");
    Shot(browser, "studio-editor-error-while-typing.png", docs: true);
    Assert.Equal(saved, File.ReadAllText(path));
  }
}
