using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace GrCis.StaticPgo;

/// <summary>
/// The training: grcis commands (one a line in a text file; '#' starts a comment) run by the given grcis with
/// dynamic profiling on and the runtime's profile written as text at exit, one dump per run. "{work}" in a line is the
/// work folder (for the runs' output files); the runs' script cache and start-up profiles are kept in it, emptied
/// first, so every training compiles its scripts (the compiler is profiled too) whatever an earlier training left.
/// </summary>
internal static class TrainingRuns
{
  public static List<string[]> Read(string path)
  {
    var runs = new List<string[]>();
    foreach (string line in File.ReadLines(path))
    {
      string text = line;
      int hash = text.IndexOf('#');
      if (hash >= 0) text = text[..hash];
      string[] words = text.Split((char[]?)null, StringSplitOptions.RemoveEmptyEntries);
      if (words.Length > 0) runs.Add(words);
    }
    return runs;
  }

  /// <summary>Runs each command; returns the dumps written. A run that fails throws with its output.</summary>
  public static List<string> Run(string dotnet, string grcis, IReadOnlyList<string[]> runs, string work, string repositoryRoot, TextWriter log)
  {
    Directory.CreateDirectory(work);
    string cache = Path.Combine(work, "cache");
    if (Directory.Exists(cache))
      Directory.Delete(cache, recursive: true);
    var dumps = new List<string>();
    for (int i = 0; i < runs.Count; i++)
    {
      string dump = Path.Combine(work, $"run-{i + 1}.txt");
      File.Delete(dump);
      var start = new ProcessStartInfo(dotnet) { WorkingDirectory = repositoryRoot };
      start.ArgumentList.Add(grcis);
      foreach (string word in runs[i]) start.ArgumentList.Add(word.Replace("{work}", work, StringComparison.Ordinal));
      start.Environment["DOTNET_TieredPGO"] = "1";
      start.Environment["DOTNET_WritePGOData"] = "1";
      start.Environment["DOTNET_PGODataPath"] = dump;
      start.Environment["GRCIS_CACHE_DIR"] = cache;
      string command = "grcis " + string.Join(' ', runs[i]);
      var clock = Stopwatch.StartNew();
      ChildProcess.Run(start, $"training run '{command}'");
      if (!File.Exists(dump))
        throw new InvalidOperationException($"training run '{command}' wrote no profile: this runtime does not write DOTNET_PGODataPath");
      log.WriteLine($"trained: {command} ({clock.Elapsed.TotalSeconds:0.0} s)");
      dumps.Add(dump);
    }
    return dumps;
  }
}
