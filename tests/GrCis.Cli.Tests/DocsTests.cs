using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Cli.Tests;

/// <summary>
/// The reference docs stay readable: no section repeated by a bad edit (one once grew a file to 9.6 MB),
/// and every relative link points at a file of the repository.
/// </summary>
public class DocsTests
{
  public static IEnumerable<object[]> Documents() =>
    Directory.GetFiles(Path.Combine(RepoPaths.Root, "docs"), "*.md").Append(Path.Combine(RepoPaths.Root, "README.md"))
      .Select(p => new object[] { Path.GetRelativePath(RepoPaths.Root, p) });

  [Theory]
  [MemberData(nameof(Documents))]
  public void Each_heading_appears_once_and_the_file_stays_small(string document)
  {
    string path = Path.Combine(RepoPaths.Root, document);
    Assert.True(new FileInfo(path).Length < 100_000, $"{document} is {new FileInfo(path).Length} bytes");
    bool fenced = false;
    var seen = new HashSet<string>();
    foreach (string line in File.ReadLines(path))
    {
      if (line.StartsWith("```"))
        fenced = !fenced;
      else if (!fenced && line.StartsWith('#'))
        Assert.True(seen.Add(line), $"{document}: heading '{line}' appears twice");
    }
  }

  [Theory]
  [MemberData(nameof(Documents))]
  public void Relative_links_point_at_files_of_the_repository(string document)
  {
    string path = Path.Combine(RepoPaths.Root, document);
    string folder = Path.GetDirectoryName(path)!;
    foreach (Match m in Regex.Matches(File.ReadAllText(path), @"\]\(([^)#\s]+)(#[^)]*)?\)"))
    {
      string target = m.Groups[1].Value;
      if (target.Contains("://") || target.StartsWith("mailto:"))
        continue;
      string full = Path.GetFullPath(Path.Combine(folder, target));
      Assert.True(File.Exists(full) || Directory.Exists(full), $"{document}: link ({target}) points at nothing");
    }
  }
}
