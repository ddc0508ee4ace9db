using System;
using System.Collections.Generic;

namespace GrCis.Hosting;

/// <summary>
/// The names of the <see cref="RenderAlgorithm"/>s as users type them (<c>grcis render --algorithm</c>, the
/// studio's <c>algorithm</c> field), kept in one place so every front end accepts the same words.
/// </summary>
public static class RenderAlgorithmNames
{
  /// <summary>Every name, in the order of <see cref="RenderAlgorithm"/>.</summary>
  public static IReadOnlyList<string> All { get; } = new[] { "raytracing", "distributed", "path" };

  /// <summary>The name of <paramref name="algorithm"/>.</summary>
  public static string Name(RenderAlgorithm algorithm) => algorithm switch
  {
    RenderAlgorithm.Distributed => "distributed",
    RenderAlgorithm.Path => "path",
    _ => "raytracing",
  };

  /// <summary>The algorithm named <paramref name="name"/> (exactly as in <see cref="All"/>), or false.</summary>
  public static bool TryParse(string? name, out RenderAlgorithm algorithm)
  {
    foreach (RenderAlgorithm a in Enum.GetValues<RenderAlgorithm>())
      if (string.Equals(name, Name(a), StringComparison.Ordinal))
      {
        algorithm = a;
        return true;
      }
    algorithm = RenderAlgorithm.RayTracing;
    return false;
  }
}
