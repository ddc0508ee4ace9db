using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Rendering.Tests.Docs;

/// <summary>
/// The code excerpts of the docs (a fenced block after an <c>&lt;!-- excerpt: path --&gt;</c> line) are the source
/// as it is: each block's lines appear, in order and contiguous, in the named file (shifted by one indentation),
/// so a change of the code that the page explains fails here until the page follows.
/// </summary>
public partial class DocExcerptTests
{
  [GeneratedRegex(@"<!-- excerpt: (?<path>\S+) -->\r?\n```csharp\r?\n(?<code>.*?)```", RegexOptions.Singleline)]
  private static partial Regex Excerpt();

  static string RepositoryRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")))
        return d.FullName;
    throw new InvalidOperationException("GrCis.sln not found above " + AppContext.BaseDirectory);
  }

  public static IEnumerable<object[]> Pages() =>
    Directory.GetFiles(Path.Combine(RepositoryRoot(), "docs"), "*.md").Select(p => new object[] { Path.GetFileName(p) });

  /// <summary>Whether <paramref name="block"/> occurs in <paramref name="source"/> at one line, all lines shifted by the same indentation.</summary>
  internal static bool Occurs(string[] block, string[] source)
  {
    for (int start = 0; start + block.Length <= source.Length; start++)
    {
      string first = source[start];
      if (!first.EndsWith(block[0], StringComparison.Ordinal) || first[..^block[0].Length].Trim().Length != 0)
        continue;
      string indent = first[..^block[0].Length];
      bool all = true;
      for (int k = 1; k < block.Length && all; k++)
        all = block[k].Length == 0 ? source[start + k].Trim().Length == 0 : source[start + k] == indent + block[k];
      if (all)
        return true;
    }
    return false;
  }

  [Theory]
  [MemberData(nameof(Pages))]
  public void Every_excerpt_is_the_current_source(string page)
  {
    string root = RepositoryRoot();
    string text = File.ReadAllText(Path.Combine(root, "docs", page));
    foreach (Match m in Excerpt().Matches(text))
    {
      string path = m.Groups["path"].Value;
      string file = Path.Combine(root, path);
      Assert.True(File.Exists(file), $"{page}: the excerpt names {path}, which does not exist");
      string[] block = m.Groups["code"].Value.Replace("\r", "").TrimEnd('\n').Split('\n');
      string[] source = File.ReadAllText(file).Replace("\r", "").Split('\n');
      Assert.True(Occurs(block, source), $"{page}: the excerpt of {path} beginning \"{block[0].Trim()}\" is not in the source as written");
    }
  }

  [Fact]
  public void How_it_works_has_excerpts_of_the_shading()
  {
    string text = File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "how-it-works.md"));
    Assert.Contains(Excerpt().Matches(text), m => m.Groups["path"].Value.EndsWith("RayTracing.cs", StringComparison.Ordinal));
  }

  [Fact]
  public void A_changed_line_is_not_found()
  {
    string[] source = ["  int F()", "  {", "    return 1;", "  }"];
    Assert.True(Occurs(["int F()", "{", "  return 1;", "}"], source));
    Assert.False(Occurs(["int F()", "{", "  return 2;", "}"], source));
    Assert.False(Occurs(["int F()", "{", "return 1;", "}"], source));
  }
}
