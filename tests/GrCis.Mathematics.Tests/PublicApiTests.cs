using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>
/// The public API of <c>OpenTK.Mathematics</c> is the one scripts, student modules and compiled homework bind to:
/// every type, member and signature is listed in <c>Data/public-api.txt</c> (see <see cref="PublicApi"/>), and the
/// assembly must offer exactly that list. A deliberate change of the API rewrites the list with
/// <c>GRCIS_WRITE_PUBLIC_API=1</c>, and the difference is reviewed with the change.
/// </summary>
public class PublicApiTests
{
  const string Namespace = "OpenTK.Mathematics";

  static readonly string ListFile = Path.Combine(AppContext.BaseDirectory, "Data", "public-api.txt");

  static Assembly Mathematics => typeof(Vector3d).Assembly;

  [Fact]
  public void The_public_API_is_the_listed_one()
  {
    List<string> actual = PublicApi.Describe(Mathematics, Namespace);
    if (Environment.GetEnvironmentVariable("GRCIS_WRITE_PUBLIC_API") == "1")
      File.WriteAllLines(Path.Combine(RepoRoot(), "tests", "GrCis.Mathematics.Tests", "Data", "public-api.txt"), actual);
    string[] expected = File.ReadAllLines(ListFile).Where(l => l.Length > 0).ToArray();

    var missing = expected.Except(actual, StringComparer.Ordinal).ToList();
    var added = actual.Except(expected, StringComparer.Ordinal).ToList();
    Assert.True(missing.Count == 0 && added.Count == 0,
      $"missing ({missing.Count}):\n  {string.Join("\n  ", missing.Take(40))}\nadded ({added.Count}):\n  {string.Join("\n  ", added.Take(40))}");
    Assert.Equal(expected, actual);
    Assert.True(expected.Length > 1000, $"only {expected.Length} lines");
  }

  static string RepoRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")))
        return d.FullName;
    throw new DirectoryNotFoundException("GrCis.sln not found above the test assembly");
  }
}
