using System.Threading;

namespace Rendering;

/// <summary>
/// GrCis's ray statistics. <see cref="allRaysCount"/> grows by every ray a render cast (added once at the
/// end of each render, as <see cref="Intersection.countRays"/>); <see cref="primaryRaysCount"/> only by
/// what code calls <see cref="IncrementRaysCounters"/> with (a student's own <c>shade</c>, for example).
/// </summary>
public static class Statistics
{
  /// <summary>Primary rays counted through <see cref="IncrementRaysCounters"/> (the library's renders do not add to it).</summary>
  public static int primaryRaysCount;

  /// <summary>All rays: every finished render adds the rays it cast, and <see cref="IncrementRaysCounters"/> adds its amount.</summary>
  public static int allRaysCount;

  /// <summary>Counts <paramref name="amount"/> rays, also as primary ones when <paramref name="primary"/>; thread-safe.</summary>
  public static void IncrementRaysCounters(int amount, bool primary)
  {
    Interlocked.Add(ref allRaysCount, amount);
    if (primary)
      Interlocked.Add(ref primaryRaysCount, amount);
  }

  /// <summary>Sets both counters to zero.</summary>
  public static void Reset()
  {
    primaryRaysCount = 0;
    allRaysCount = 0;
  }
}
