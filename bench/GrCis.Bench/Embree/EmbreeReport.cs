using System.Collections.Generic;
using System.Linq;

namespace GrCis.Bench.Embree;

/// <summary>What one <see cref="EmbreeComparison"/> run measured.</summary>
public sealed class EmbreeReport
{
  /// <summary>Triangles of the mesh.</summary>
  public int Triangles { get; init; }

  /// <summary>Median seconds of the library's mesh BVH build (all cores), and of Embree's MEDIUM build on one thread and on all.</summary>
  public double LibraryBuild { get; set; }
  public double EmbreeBuild1 { get; set; }
  public double EmbreeBuildAll { get; set; }

  /// <summary>Bytes the library's last build round allocated (all threads; what the mesh keeps included).</summary>
  public long LibraryBuildBytes { get; set; }

  /// <summary>The one-minute load average when the run started (<see cref="EmbreeTsv.LoadAverage"/>), or null.</summary>
  public string? LoadBefore { get; init; }

  public List<EmbreeRow> Rows { get; } = new();

  /// <summary>
  /// Embree's single-ray rate on <paramref name="row"/>'s rays at its thread count: the first row of that set and count
  /// (each set's queries are measured with Embree's single-ray query first).
  /// </summary>
  public double ReferenceMrays(EmbreeRow row) => Rows.First(r => r.Rays == row.Rays && r.Threads == row.Threads).Mrays;

  /// <summary>Rays, over all rows' first thread count, whose hit or miss differed from Embree's.</summary>
  public int Mismatches => Rows.Where(r => r.Threads == Rows[0].Threads).Sum(r => r.Mismatches);
}
