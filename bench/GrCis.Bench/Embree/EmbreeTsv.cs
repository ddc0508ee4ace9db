using System;
using System.Globalization;
using System.IO;

namespace GrCis.Bench.Embree;

/// <summary>
/// An <see cref="EmbreeReport"/> as a tab-separated table (<c>embree --tsv FILE</c>), the input of <c>plots --embree</c>:
/// <c># key: value</c> lines (date, machine, mesh, command, the builds' times), then one row per ray set, query and
/// thread count with the library's (or Embree's) rate, Embree's single-ray rate on the same rays and the time ratio
/// (time ÷ Embree's single-ray time: 1 for Embree's own row), and one row for the build (library ÷ Embree MEDIUM on
/// one thread; not measured columns are "-").
/// </summary>
public static class EmbreeTsv
{
  /// <summary>The column names, in order.</summary>
  public static readonly string[] Columns = { "rays", "query", "threads", "mrays", "embree_mrays", "time_ratio", "mismatches" };

  /// <summary>The <c>rays</c> cell of the build row.</summary>
  public const string BuildRays = "build";

  /// <summary>Writes the table to <paramref name="file"/> whole or not at all (a temporary file moved into place).</summary>
  public static void Write(EmbreeReport report, string mesh, string command, string file)
  {
    string part = file + ".part";
    using (var w = new StreamWriter(part))
      Write(report, mesh, command, w);
    File.Move(part, file, overwrite: true);
  }

  /// <summary>Writes the table to <paramref name="w"/>.</summary>
  public static void Write(EmbreeReport report, string mesh, string command, TextWriter w)
  {
    w.NewLine = "\n";
    w.WriteLine($"# date: {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC");
    w.WriteLine($"# machine: {Environment.ProcessorCount} logical CPUs, {Processor()}, {Environment.OSVersion.VersionString}, .NET {Environment.Version}");
    string? loadAfter = LoadAverage();
    if (report.LoadBefore != null || loadAfter != null)
      w.WriteLine($"# load average (1 min): {report.LoadBefore ?? "?"} at the start, {loadAfter ?? "?"} at the end (other work on the machine disturbs the ratios)");
    if (Commit() is string commit)
      w.WriteLine($"# commit: {commit}");
    w.WriteLine($"# mesh: {mesh}, {report.Triangles} triangles");
    w.WriteLine($"# command: {command}");
    w.WriteLine(Inv($"# build: library mesh BVH {report.LibraryBuild * 1e3:F1} ms (all cores); Embree MEDIUM {report.EmbreeBuild1 * 1e3:F1} ms (1 thread), {report.EmbreeBuildAll * 1e3:F1} ms (all threads)"));
    w.WriteLine("# time_ratio: the query's time over Embree's single-ray query's time on the same rays in the same process");
    w.WriteLine(string.Join('\t', Columns));
    foreach (EmbreeRow row in report.Rows)
    {
      double reference = report.ReferenceMrays(row);
      w.WriteLine(Inv($"{row.Rays}\t{row.Query}\t{row.Threads}\t{row.Mrays:F4}\t{reference:F4}\t{reference / row.Mrays:F4}\t{row.Mismatches}"));
    }
    if (report.EmbreeBuild1 > 0.0)
      w.WriteLine(Inv($"{BuildRays}\tmesh BVH (all cores) / Embree MEDIUM (1 thread)\t-\t-\t-\t{report.LibraryBuild / report.EmbreeBuild1:F4}\t0"));
  }

  static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);

  /// <summary>The commit of the working folder's repository (with "+changes" when it has uncommitted ones), or null.</summary>
  static string? Commit()
  {
    try
    {
      string Git(string arguments)
      {
        var start = new System.Diagnostics.ProcessStartInfo("git", arguments) { RedirectStandardOutput = true, RedirectStandardError = true };
        using var git = System.Diagnostics.Process.Start(start)!;
        string text = git.StandardOutput.ReadToEnd().Trim();
        git.WaitForExit();
        return git.ExitCode == 0 ? text : throw new IOException("git " + arguments);
      }
      string head = Git("rev-parse --short HEAD");
      return Git("status --porcelain --untracked-files=no").Length > 0 ? head + "+changes" : head;
    }
    catch (Exception e) when (e is IOException or System.ComponentModel.Win32Exception or InvalidOperationException)
    {
      return null;   // no git, or not in a repository
    }
  }

  /// <summary>The one-minute load average where the system tells it (Linux), else null.</summary>
  public static string? LoadAverage()
  {
    try
    {
      return File.Exists("/proc/loadavg") ? File.ReadAllText("/proc/loadavg").Split(' ')[0] : null;
    }
    catch (IOException)
    {
      return null;
    }
  }

  /// <summary>The processor's model name where the system tells it (Linux), else its architecture.</summary>
  static string Processor()
  {
    try
    {
      if (File.Exists("/proc/cpuinfo"))
        foreach (string line in File.ReadLines("/proc/cpuinfo"))
          if (line.StartsWith("model name", StringComparison.Ordinal) && line.IndexOf(':') is int colon and > 0)
            return line[(colon + 1)..].Trim();
    }
    catch (IOException)
    {
    }
    return System.Runtime.InteropServices.RuntimeInformation.ProcessArchitecture.ToString();
  }
}
