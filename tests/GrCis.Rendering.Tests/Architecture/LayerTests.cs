using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace GrCis.Rendering.Tests.Architecture;

/// <summary>
/// The folders of src/GrCis.Rendering form layers (docs/architecture.md, the <c>layers</c> block): a file names only
/// types and members declared in its own folder's layer or below, and no dependency cycle spans more than
/// <see cref="LargestCycle"/> folders. Measured on the sources compiled with Roslyn (<see cref="FolderGraph"/>).
/// </summary>
public partial class LayerTests
{
  /// <summary>The most folders one dependency cycle may join (the one left: Accel, ImageFunctions, Renderers, Execution).</summary>
  const int LargestCycle = 4;

  static readonly Lazy<FolderGraph> graph = new(() =>
    FolderGraph.Build(Path.Combine(RepositoryRoot(), "src", "GrCis.Rendering"),
      FolderGraph.References(typeof(OpenTK.Mathematics.Vector3d).Assembly.Location, typeof(StbImageSharp.ImageResult).Assembly.Location)));

  static string RepositoryRoot()
  {
    for (DirectoryInfo? d = new(AppContext.BaseDirectory); d != null; d = d.Parent)
      if (File.Exists(Path.Combine(d.FullName, "GrCis.sln")))
        return d.FullName;
    throw new InvalidOperationException("GrCis.sln not found above " + AppContext.BaseDirectory);
  }

  [GeneratedRegex(@"```layers\r?\n(?<body>.*?)```", RegexOptions.Singleline)]
  private static partial Regex LayersBlock();

  /// <summary>The picture: layers top to bottom (each a list of folders), and the dependencies allowed to go up.</summary>
  internal static (List<(string Name, string[] Folders)> Layers, HashSet<(string, string)> Allowed) Picture(string markdown)
  {
    Match m = LayersBlock().Match(markdown);
    Assert.True(m.Success, "docs/architecture.md has no ```layers block.");
    var layers = new List<(string, string[])>();
    var allowed = new HashSet<(string, string)>();
    foreach (string raw in m.Groups["body"].Value.Split('\n'))
    {
      string line = raw.Trim();
      if (line.Length == 0)
        continue;
      int colon = line.IndexOf(':');
      Assert.True(colon > 0, $"A line of the layers block is not 'name: folders': {line}");
      string name = line[..colon].Trim();
      string rest = line[(colon + 1)..];
      if (name == "allowed")
      {
        foreach (string pair in rest.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
          string[] ends = pair.Split("->", StringSplitOptions.TrimEntries);
          Assert.True(ends.Length == 2, $"An allowed dependency is not 'From -> To': {pair}");
          allowed.Add((ends[0], ends[1]));
        }
        continue;
      }
      layers.Add((name, rest.Split(' ', StringSplitOptions.RemoveEmptyEntries)));
    }
    return (layers, allowed);
  }

  [Fact]
  public void The_library_compiles_for_the_measurement()
  {
    Assert.True(graph.Value.Errors.Count == 0, string.Join("\n", graph.Value.Errors.Take(10)));
    Assert.True(graph.Value.Dependencies.Count > 500, "Too few dependencies were found: the semantic model binds nothing.");
  }

  [Fact]
  public void No_dependency_cycle_joins_more_folders_than_the_bound()
  {
    List<string> largest = graph.Value.Components()[0];
    if (largest.Count <= LargestCycle)
      return;
    var members = largest.ToHashSet();
    string edges = string.Join("\n", graph.Value.Dependencies
      .Where(d => members.Contains(d.From) && members.Contains(d.To))
      .GroupBy(d => (d.From, d.To))
      .Select(g => $"  {g.Key.From} -> {g.Key.To}: {g.First()}"));
    Assert.Fail($"{largest.Count} folders form one dependency cycle (at most {LargestCycle}): {string.Join(", ", largest)}\n{edges}");
  }

  [Fact]
  public void Every_dependency_goes_to_the_same_layer_or_one_below_as_the_architecture_page_draws_them()
  {
    var (layers, allowed) = Picture(File.ReadAllText(Path.Combine(RepositoryRoot(), "docs", "architecture.md")));
    var rank = new Dictionary<string, int>();
    for (int i = 0; i < layers.Count; i++)
      foreach (string folder in layers[i].Folders)
        Assert.True(rank.TryAdd(folder, layers.Count - i), $"Folder {folder} is in two layers of the picture.");
    string[] missing = graph.Value.Folders.Where(f => f.Length > 0 && !rank.ContainsKey(f)).ToArray();
    Assert.True(missing.Length == 0, "Folders of the library missing from the picture: " + string.Join(", ", missing));
    string[] gone = rank.Keys.Where(f => !graph.Value.Folders.Contains(f)).ToArray();
    Assert.True(gone.Length == 0, "Folders in the picture that the library does not have: " + string.Join(", ", gone));

    string[] upward = graph.Value.Dependencies
      .Where(d => d.From.Length > 0 && rank[d.To] > rank[d.From] && !allowed.Contains((d.From, d.To)))
      .Select(d => $"{d.File}:{d.Line} names {d.Name}: {d.From} (layer {layers[layers.Count - rank[d.From]].Name}) -> {d.To} (layer {layers[layers.Count - rank[d.To]].Name})")
      .ToArray();
    Assert.True(upward.Length == 0, $"{upward.Length} dependencies go up a layer:\n" + string.Join("\n", upward.Take(40)));

    string[] unused = allowed.Where(a => !graph.Value.Dependencies.Any(d => (d.From, d.To) == a)).Select(a => $"{a.Item1} -> {a.Item2}").ToArray();
    Assert.True(unused.Length == 0, "Allowed exceptions the code no longer has (remove them from the picture): " + string.Join(", ", unused));
  }

  [Fact]
  public void The_picture_parser_reads_layers_top_to_bottom_and_the_allowed_exceptions()
  {
    var (layers, allowed) = Picture("x\n```layers\ntop:    A B\nbottom: C\nallowed: C -> A, C -> B\n```\n");
    Assert.Equal(new[] { "top", "bottom" }, layers.Select(l => l.Name));
    Assert.Equal(new[] { "A", "B" }, layers[0].Folders);
    Assert.Contains(("C", "A"), allowed);
    Assert.Contains(("C", "B"), allowed);
  }

  [Fact]
  public void Tarjan_finds_the_cycles_of_a_small_graph()
  {
    // Checked through the real graph's shape: every folder is in exactly one component.
    var components = graph.Value.Components();
    Assert.Equal(graph.Value.Folders.Count, components.Sum(c => c.Count));
    Assert.Equal(graph.Value.Folders.OrderBy(f => f, StringComparer.Ordinal), components.SelectMany(c => c).OrderBy(f => f, StringComparer.Ordinal));
  }
}
