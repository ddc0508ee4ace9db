using System.Linq;
using System.Text;
using System.Xml.Linq;
using Microsoft.CodeAnalysis;

namespace GrCis.Editing;

/// <summary>Plain text from a symbol's XML doc comment (summary, a parameter's text), as an editor shows it.</summary>
internal static class DocComments
{
  public static string? Summary(ISymbol symbol) => Element(symbol, e => e.Name == "summary");

  public static string? Parameter(IParameterSymbol parameter) =>
    parameter.ContainingSymbol is { } owner
      ? Element(owner, e => e.Name == "param" && (string?)e.Attribute("name") == parameter.Name)
      : null;

  static string? Element(ISymbol symbol, System.Func<XElement, bool> pick)
  {
    string? xml = symbol.GetDocumentationCommentXml(expandIncludes: false);
    if (string.IsNullOrWhiteSpace(xml))
      return null;
    XElement root;
    try
    {
      root = XElement.Parse(xml);
    }
    catch (System.Xml.XmlException)
    {
      return null; // a doc comment that is not well-formed: show nothing rather than its markup
    }
    XElement? element = root.Elements().FirstOrDefault(pick);
    if (element is null)
      return null;
    string text = Flatten(element).Trim();
    return text.Length == 0 ? null : text;
  }

  const char Paragraph = '\u2029';

  // Text with <see cref="T:Rendering.Sphere"/> as "Sphere", <c>x</c> as "x", each <para> on its own line.
  static string Flatten(XElement element)
  {
    var text = new StringBuilder();
    Append(element, text);
    return string.Join("\n", text.ToString().Split(Paragraph)
      .Select(p => string.Join(" ", p.Split((char[]?)null, System.StringSplitOptions.RemoveEmptyEntries)))
      .Where(p => p.Length > 0));
  }

  static void Append(XElement element, StringBuilder text)
  {
    foreach (XNode node in element.Nodes())
    {
      if (node is XText t)
        text.Append(t.Value);
      else if (node is XElement e)
      {
        if (e.Name == "see" || e.Name == "seealso" || e.Name == "paramref" || e.Name == "typeparamref")
          text.Append(Reference(e));
        else if (e.Name == "para" || e.Name == "br")
        {
          text.Append(Paragraph);
          Append(e, text);
          text.Append(Paragraph);
        }
        else
          Append(e, text);
      }
    }
  }

  static string Reference(XElement e)
  {
    string? name = (string?)e.Attribute("cref") ?? (string?)e.Attribute("name") ?? (string?)e.Attribute("langword") ?? (string?)e.Attribute("href");
    if (!e.IsEmpty && e.Value.Length > 0)
      return e.Value;
    if (name is null)
      return "";
    int colon = name.IndexOf(':');
    if (colon == 1)
      name = name[2..];
    int paren = name.IndexOf('(');
    if (paren >= 0)
      name = name[..paren];
    int dot = name.LastIndexOf('.');
    return dot >= 0 ? name[(dot + 1)..] : name;
  }
}
