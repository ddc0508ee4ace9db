using System;
using System.Collections.Generic;
using System.IO;
using System.Text.Json;

namespace GrCis.Bench.Plots;

/// <summary>
/// Results of <c>grcis bench --json</c>: either its output as printed (one array, one run) or a recorded file
/// <c>{"date", "machine", "commit", "command", "runs": [{"label", "results": [ … ]}]}</c> whose results are
/// such arrays, so the date, machine and commit travel with the numbers.
/// </summary>
public sealed class BenchJson
{
  public required string File { get; init; }
  public required IReadOnlyDictionary<string, string> Header { get; init; }
  public required IReadOnlyList<BenchRun> Runs { get; init; }

  public static BenchJson Read(string file)
  {
    if (!System.IO.File.Exists(file))
      throw new PlotInputException(file, 0, "no such file");
    JsonDocument doc;
    try
    {
      doc = JsonDocument.Parse(System.IO.File.ReadAllText(file));
    }
    catch (JsonException e)
    {
      throw new PlotInputException(file, (int)(e.LineNumber ?? -1) + 1, "not JSON: " + e.Message);
    }
    using (doc)
    {
      var header = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
      var runs = new List<BenchRun>();
      JsonElement root = doc.RootElement;
      if (root.ValueKind == JsonValueKind.Array)
        runs.Add(new BenchRun("", Results(file, "", root)));
      else if (root.ValueKind == JsonValueKind.Object)
      {
        foreach (JsonProperty p in root.EnumerateObject())
          if (p.Value.ValueKind == JsonValueKind.String)
            header[p.Name] = p.Value.GetString()!;
        if (!root.TryGetProperty("runs", out JsonElement list) || list.ValueKind != JsonValueKind.Array)
          throw new PlotInputException(file, 0, "an object needs a \"runs\" array (or give the bench's own array)");
        int n = 0;
        foreach (JsonElement run in list.EnumerateArray())
        {
          n++;
          string label = run.TryGetProperty("label", out JsonElement l) && l.ValueKind == JsonValueKind.String ? l.GetString()! : $"run {n}";
          if (!run.TryGetProperty("results", out JsonElement results) || results.ValueKind != JsonValueKind.Array)
            throw new PlotInputException(file, 0, $"run '{label}': no \"results\" array");
          runs.Add(new BenchRun(label, Results(file, label, results)));
        }
      }
      else
        throw new PlotInputException(file, 1, "expected an array of bench results or an object with \"runs\"");
      if (runs.Count == 0)
        throw new PlotInputException(file, 0, "no runs");
      return new BenchJson { File = file, Header = header, Runs = runs };
    }
  }

  static List<BenchPoint> Results(string file, string run, JsonElement array)
  {
    var list = new List<BenchPoint>();
    int i = 0;
    foreach (JsonElement e in array.EnumerateArray())
    {
      i++;
      string where = (run.Length > 0 ? $"run '{run}', " : "") + $"result {i}";
      if (e.ValueKind != JsonValueKind.Object)
        throw new PlotInputException(file, 0, $"{where}: not an object");
      string id = Str(file, where, e, "id");
      where += $" ('{id}')";
      list.Add(new BenchPoint
      {
        Id = id,
        Name = Str(file, where, e, "name"),
        Threads = (int)(Num(file, where, e, "threads") ?? 0),
        Seconds = Num(file, where, e, "seconds"),
        CpuSeconds = Num(file, where, e, "cpuSeconds"),
        Rays = Num(file, where, e, "rays"),
        Triangles = Num(file, where, e, "triangles"),
        OneThreadSeconds = Num(file, where, e, "oneThreadSeconds"),
        ThreadsSeconds = Num(file, where, e, "threadsSeconds"),
        Scaling = Num(file, where, e, "scaling"),
        ScalingCeiling = Num(file, where, e, "scalingCeiling"),
      });
    }
    return list;
  }

  static string Str(string file, string where, JsonElement e, string name) =>
    e.TryGetProperty(name, out JsonElement v) && v.ValueKind == JsonValueKind.String
      ? v.GetString()!
      : throw new PlotInputException(file, 0, $"{where}: no string field \"{name}\"");

  /// <summary>A numeric field; absent or null is null, anything else that is not a finite number fails.</summary>
  static double? Num(string file, string where, JsonElement e, string name)
  {
    if (!e.TryGetProperty(name, out JsonElement v) || v.ValueKind == JsonValueKind.Null)
      return null;
    if (v.ValueKind != JsonValueKind.Number || !double.IsFinite(v.GetDouble()))
      throw new PlotInputException(file, 0, $"{where}: field \"{name}\" is not a number: {v}");
    return v.GetDouble();
  }
}

/// <summary>One <c>grcis bench</c> invocation's results.</summary>
public sealed record BenchRun(string Label, IReadOnlyList<BenchPoint> Results);

/// <summary>The fields of one bench result the plots use (null where the run did not measure them).</summary>
public sealed record BenchPoint
{
  public required string Id { get; init; }
  public required string Name { get; init; }
  public int Threads { get; init; }
  public double? Seconds { get; init; }
  public double? CpuSeconds { get; init; }
  public double? Rays { get; init; }
  public double? Triangles { get; init; }
  public double? OneThreadSeconds { get; init; }
  public double? ThreadsSeconds { get; init; }
  public double? Scaling { get; init; }
  public double? ScalingCeiling { get; init; }
}
