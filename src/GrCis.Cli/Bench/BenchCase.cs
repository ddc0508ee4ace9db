using System;
using GrCis.Cli.Jobs;
using Rendering;

namespace GrCis.Cli.Bench;

/// <summary>
/// One scene of the benchmark suite: rendered at <see cref="Size"/> × <see cref="Spp"/> on the fast path
/// and, for the speedup, at the smaller <see cref="SlowSize"/> × <see cref="SlowSpp"/> on the faithful path
/// (<c>--accel none</c> would take minutes at full size); speedups compare rays per second.
/// </summary>
public sealed record BenchCase(string Id, string Name, Func<IRayScene> Build, ImageSize Size, int Spp, ImageSize SlowSize, int SlowSpp)
{
  /// <summary>What the scene holds (members, triangles …), for the report.</summary>
  public string Description { get; init; } = "";

  /// <summary>For mesh cases: the mesh's triangle count, asked after <see cref="Build"/> (an OBJ file is read there).</summary>
  public Func<long>? Triangles { get; init; }
}
