using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.RegularExpressions;
using System.Threading.Tasks;
using GrCis.Editing;
using GrCis.Studio;

namespace GrCis.Bench;

/// <summary>
/// <c>GrCis.Bench editor SCRIPTS_DIR</c>: how fast the studio editor's services answer on real scripts. For every
/// script, a completion at each member access (the text cut just after the dot, as while typing), signature help
/// inside each call's parentheses and a hover on each identifier (and a completion list without descriptions, and one
/// entry described afterwards, as the page asks when an undescribed entry is selected): the first call (cold: metadata loading) and then
/// median and 95th percentile of the warm calls, in ms, each against the issue's 150 ms budget; and, as the floor
/// measured in the same run, a bare Roslyn lookup of the names visible at the same positions. Also the check of a draft
/// (the whole text compiled as the script, <c>ScriptHost.Check</c>), which marks errors while typing.
/// Completion in the middle of a script as a student types it (a member's name cut after its first letter, the rest of
/// the file after the caret), and, first of all in a fresh process, what a page meets in a studio just started as
/// <c>grcis studio</c> starts it (language services warming in the background): how long after the start the studio
/// answers, and how long the first and second completions then take.
/// </summary>
internal static class EditorMeasure
{
  const double BudgetMs = 150;

  public static int Run(string[] args)
  {
    if (args.Length < 1 || !Directory.Exists(args[0]))
    {
      Console.Error.WriteLine("usage: GrCis.Bench editor SCRIPTS_DIR   (a folder of scene scripts, e.g. scripts/)");
      return 2;
    }
    string[] scripts = Directory.GetFiles(args[0], "*.cs").OrderBy(f => f, StringComparer.Ordinal).ToArray();
    var total = Stopwatch.StartNew();
    (double answering, double first, double second) = AfterStudioStart(args[0], scripts).GetAwaiter().GetResult();
    using var assistant = new ScriptAssistant();
    var cold = Stopwatch.StartNew();
    assistant.CompleteAsync("scene.", 6).GetAwaiter().GetResult();
    cold.Stop();

    var completion = new List<double>();
    var bare = new List<double>();
    var describe = new List<double>();
    var signature = new List<double>();
    var hover = new List<double>();
    var floor = new List<double>();
    var check = new List<double>();
    var midScript = new List<double>();
    using var host = new GrCis.Scripting.ScriptHost();
    host.Check("scene.Intersectable = null;", Path.Combine(args[0], "Warm-up.cs"));
    foreach (string file in scripts)
    {
      string text = File.ReadAllText(file);
      foreach (int dot in Positions(text, c => c == '.').Take(40))
      {
        string typed = text[..(dot + 1)];
        CompletionResult? list = null;
        completion.Add(Time(() => list = assistant.CompleteAsync(typed, typed.Length).GetAwaiter().GetResult()));
        bare.Add(Time(() => assistant.CompleteAsync(typed, typed.Length, described: 0).GetAwaiter().GetResult()));
        if (list!.Items.Count > ScriptAssistant.DescribedCompletions)
          describe.Add(Time(() => assistant.DescribeAsync(typed, typed.Length, list.Items[^1].Label).GetAwaiter().GetResult()));
        floor.Add(Time(() => assistant.LookupFloorAsync(typed, typed.Length).GetAwaiter().GetResult()));
      }
      foreach ((string cut, int caret) in MidScript(text).Take(40))
        midScript.Add(Time(() => assistant.CompleteAsync(cut, caret).GetAwaiter().GetResult()));
      // A draft that differs from everything compiled before (a new comment), as each keystroke's text does.
      for (int i = 0; i < 3; i++)
        check.Add(Time(() => host.Check(text + $"\n// draft {i}\n", file)));
      foreach (int paren in Positions(text, c => c == '(').Take(20))
        signature.Add(Time(() => assistant.SignatureAsync(text, paren + 1).GetAwaiter().GetResult()));
      foreach (int start in Positions(text, char.IsUpper).Take(20))
        hover.Add(Time(() => assistant.HoverAsync(text, start + 1).GetAwaiter().GetResult()));
    }

    Console.WriteLine($"editor services on {scripts.Length} scripts ({Environment.ProcessorCount} cores), ms; budget {BudgetMs} ms warm");
    Console.WriteLine($"studio started: answers after {answering,6:F0}; first completion {first,6:F0}, second {second,6:F0}");
    Console.WriteLine($"first completion (cold)   {cold.Elapsed.TotalMilliseconds,8:F0}");
    Report($"completion, {ScriptAssistant.DescribedCompletions} described", completion, floor);
    Report("completion mid-script", midScript, floor);
    Report("completion, none described", bare, floor);
    Report("describe one more entry", describe, floor);
    Report("signature help", signature, floor);
    Report("hover", hover, floor);
    Report("name lookup (floor)", floor, floor);
    Report("check of a draft (compile)", check, floor);
    Console.WriteLine($"whole run {total.Elapsed.TotalSeconds:F1} s");
    return 0;
  }

  /// <summary>
  /// A studio started as <c>grcis studio</c> starts it, asked as a page asks as soon as it can: ms from the start until
  /// it answers its status, then the first completion's and the second's time (a member cut mid-script).
  /// </summary>
  static async Task<(double Answering, double First, double Second)> AfterStudioStart(string folder, string[] scripts)
  {
    var clock = Stopwatch.StartNew();
    await using StudioServer studio = await StudioServer.StartAsync(new StudioOptions { Paths = [folder], WarmEditor = true }, new List<string>());
    using var client = new HttpClient { BaseAddress = new Uri(new Uri(studio.Url).GetLeftPart(UriPartial.Authority)) };
    client.DefaultRequestHeaders.Add(AccessGuard.HeaderName, studio.Token);
    (await client.GetAsync("/api/status")).EnsureSuccessStatusCode();
    double answering = clock.Elapsed.TotalMilliseconds;
    (string text, int caret) = scripts.Select(f => MidScript(File.ReadAllText(f)).Skip(3).FirstOrDefault()).First(p => p.Text is not null);
    double Complete()
    {
      long start = Stopwatch.GetTimestamp();
      client.PostAsJsonAsync("/api/editor/complete", new { text, position = caret }).GetAwaiter().GetResult().EnsureSuccessStatusCode();
      return Stopwatch.GetElapsedTime(start).TotalMilliseconds;
    }
    double first = Complete();
    return (answering, first, Complete());
  }

  // A member's name after a dot cut after its first letter, the rest of the file kept: the text and the caret.
  static IEnumerable<(string Text, int Caret)> MidScript(string text)
  {
    foreach (Match m in Regex.Matches(text, @"(?<=[A-Za-z0-9_)\]]\.)[A-Za-z_]\w+"))
      yield return (text.Remove(m.Index + 1, m.Length - 1), m.Index + 1);
  }

  static IEnumerable<int> Positions(string text, Func<char, bool> pick)
  {
    for (int i = 0; i < text.Length; i++)
      if (pick(text[i]))
        yield return i;
  }

  static double Time(Action action)
  {
    long start = Stopwatch.GetTimestamp();
    action();
    return Stopwatch.GetElapsedTime(start).TotalMilliseconds;
  }

  static void Report(string name, List<double> ms, List<double> floor)
  {
    if (ms.Count == 0)
      return;
    double[] sorted = ms.OrderBy(x => x).ToArray();
    double median = sorted[sorted.Length / 2], p95 = sorted[(int)(0.95 * (sorted.Length - 1))];
    double floorMedian = floor.OrderBy(x => x).ElementAt(floor.Count / 2);
    Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
      "{0,-26}{1,8:F1} median {2,8:F1} p95 {3,8:F1} max  n={4,-5} median/budget {5:F2}  median/floor {6:F1}",
      name, median, p95, sorted[^1], sorted.Length, median / BudgetMs, median / floorMedian));
  }
}
