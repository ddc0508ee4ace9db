namespace GrCis.Cli.Bench;

/// <summary>Measured numbers of one <see cref="BenchCase"/> (JSON field names are these property names).</summary>
public sealed record BenchResult
{
  public required string Id { get; init; }
  public required string Name { get; init; }
  public string Description { get; init; } = "";
  public required string Size { get; init; }
  public int Spp { get; init; }

  /// <summary>Triangles of the case's mesh (mesh cases only, else null): the x axis of mesh-size scaling.</summary>
  public long? Triangles { get; init; }
  public int Threads { get; init; }
  /// <summary>Wall-clock seconds of the timed render.</summary>
  public double Seconds { get; init; }

  /// <summary>Processor seconds of this process during the timed render (all threads): robust on a loaded machine.</summary>
  public double CpuSeconds { get; init; }
  public long Rays { get; init; }
  public double RaysPerSecond { get; init; }

  /// <summary>Seconds of the first warm-up render: preparing the scene (flatten, BVHs, mesh BVH) and its JIT.</summary>
  public double PrepareSeconds { get; init; }

  /// <summary>Faithful path (<c>--accel none</c>) at <see cref="SlowSize"/>; null when skipped.</summary>
  public string? SlowSize { get; init; }
  public int SlowSpp { get; init; }
  public double? SlowSeconds { get; init; }
  public double? SlowRaysPerSecond { get; init; }

  /// <summary>Fast rays/s over faithful rays/s, measured in the same run.</summary>
  public double? Speedup { get; init; }

  /// <summary>Fast-path queries that fell back to the faithful path (rays starting inside a solid …).</summary>
  public long Fallbacks { get; init; }

  /// <summary>With <c>--scaling</c>: best fast-path seconds on one thread and on <see cref="Threads"/>, alternated.</summary>
  public double? OneThreadSeconds { get; init; }
  public double? ThreadsSeconds { get; init; }

  /// <summary>One-thread seconds over N-thread seconds (ideal: N); compare with <see cref="ScalingCeiling"/>.</summary>
  public double? Scaling { get; init; }

  /// <summary>The machine's own N-thread throughput gain on register-only arithmetic (<see cref="ParallelCeiling"/>).</summary>
  public double? ScalingCeiling { get; init; }
}
