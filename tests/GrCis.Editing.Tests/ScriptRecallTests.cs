using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp.Syntax;
using Xunit.Abstractions;

namespace GrCis.Editing.Tests;

/// <summary>
/// The services over the scripts students start from (scripts/ and the template's Scene.cs): completion at a name cut
/// after its first letters, anywhere in a script with the rest of the file after the caret, and signature help in
/// every argument list.
/// </summary>
public sealed class ScriptRecallTests(AssistantFixture fixture, ITestOutputHelper output) : IClassFixture<AssistantFixture>
{
  readonly ScriptAssistant assistant = fixture.Assistant;

  /// <summary>
  /// Probes per script and per kind (the rest of the line kept, or deleted) when not all are asked for: spread evenly
  /// over the script, 2 × 20 of each of the 25 scripts (962 completions, of which 300 members after a dot; 1.5 min on
  /// two busy cores). Every probe, 7048, with <c>GRCIS_RECALL_ALL=1</c>.
  /// </summary>
  const int SampledPerScript = 20;

  [Fact]
  public async Task A_name_cut_after_its_first_letters_is_offered_anywhere_in_every_script()
  {
    bool all = System.Environment.GetEnvironmentVariable("GRCIS_RECALL_ALL") == "1";
    var probes = new List<CompletionProbe>();
    foreach (string file in RepoScripts.All)
    {
      string source = File.ReadAllText(file);
      SemanticModel model = await assistant.ModelAsync(source);
      SyntaxNode root = await model.SyntaxTree.GetRootAsync();
      List<CompletionProbe> found = CompletionProbe.In(Path.GetFileName(file), source, root, model).ToList();
      foreach (bool last in new[] { false, true })
      {
        List<CompletionProbe> kind = found.Where(p => p.LastOnLine == last).ToList();
        int stride = all ? 1 : System.Math.Max(1, (kind.Count + SampledPerScript - 1) / SampledPerScript);
        probes.AddRange(kind.Where((_, i) => i % stride == 0));
      }
    }
    var watch = Stopwatch.StartNew();
    // Two at a time: the assistant answers each call on its own snapshot.
    int[] positions = new int[probes.Count];
    int[] counts = new int[probes.Count];
    string[] firsts = new string[probes.Count];
    await Parallel.ForEachAsync(Enumerable.Range(0, probes.Count), new ParallelOptions { MaxDegreeOfParallelism = 2 }, async (k, cancel) =>
    {
      CompletionResult result = await assistant.CompleteAsync(probes[k].Text, probes[k].Caret, described: 0, cancel);
      positions[k] = result.Items.ToList().FindIndex(i => probes[k].Offered(i.Label));
      counts[k] = result.Items.Count;
      firsts[k] = string.Join(", ", result.Items.Take(6).Select(i => i.Label));
    });
    double seconds = watch.Elapsed.TotalSeconds;
    bool ok = true;
    foreach (bool last in new[] { false, true })
    {
      int[] kind = Enumerable.Range(0, probes.Count).Where(k => probes[k].LastOnLine == last).ToArray();
      int offered = kind.Count(k => positions[k] >= 0);
      int[] members = kind.Where(k => probes[k].IsMember).ToArray();
      int top5 = members.Count(k => positions[k] is >= 0 and < 5);
      output.WriteLine($"{(last ? "rest of the line deleted" : "rest of the line kept")}: {kind.Length} names, {offered} offered ({100.0 * offered / kind.Length:F1} %); " +
                       $"{members.Length} members, {top5} in the top 5 ({100.0 * top5 / members.Length:F1} %)");
      ok &= offered >= 0.99 * kind.Length && top5 >= 0.99 * members.Length;
    }
    output.WriteLine($"{probes.Count} completions in {seconds:F1} s");
    for (int k = 0; k < probes.Count; k++)
    {
      CompletionProbe p = probes[k];
      if (positions[k] < 0 || p.IsMember && positions[k] >= 5)
        output.WriteLine($"{p.File}:{p.Line}{(p.LastOnLine ? " (line cut)" : "")} {p.Text[System.Math.Max(0, p.Caret - 12)..p.Caret].Replace('\n', '⏎')}| for {p.Name}: " +
                         (positions[k] < 0 ? "missing" : $"at {positions[k]}") + $" of {counts[k]} [{firsts[k]}]");
    }
    Assert.True(ok, "recall under 99 %, see the output");
  }

  [Fact]
  public async Task Signature_help_in_every_argument_list_shows_the_overload_the_compiler_binds()
  {
    int probes = 0, agree = 0;
    var misses = new List<string>();
    foreach (string file in RepoScripts.All)
    {
      string source = File.ReadAllText(file);
      SemanticModel model = await assistant.ModelAsync(source);
      SyntaxNode root = await model.SyntaxTree.GetRootAsync();
      foreach (ArgumentListSyntax args in root.DescendantNodes().OfType<ArgumentListSyntax>())
      {
        if (args.Parent is not (InvocationExpressionSyntax or BaseObjectCreationExpressionSyntax) ||
            model.GetSymbolInfo(args.Parent).Symbol is not IMethodSymbol bound)
          continue;
        string expected = Signatures.Label(bound);
        foreach (int caret in args.Arguments.GetSeparators().Select(c => c.Span.End).Prepend(args.OpenParenToken.Span.End))
        {
          SignatureHelp? help = await assistant.SignatureAsync(source, caret);
          string? shown = help is null ? null : help.Signatures[help.Active].Label;
          probes++;
          if (shown == expected)
            agree++;
          else
            misses.Add($"{Path.GetFileName(file)}:{args.GetLocation().GetLineSpan().StartLinePosition.Line + 1} col {caret - source.LastIndexOf('\n', caret - 1)}: {shown ?? "none"} instead of {expected}");
        }
      }
    }
    output.WriteLine($"{probes} carets, {agree} agree ({100.0 * agree / probes:F1} %)");
    foreach (string miss in misses)
      output.WriteLine(miss);
    Assert.True(agree >= 0.99 * probes, $"{agree} of {probes} carets show the bound overload");
  }
}
