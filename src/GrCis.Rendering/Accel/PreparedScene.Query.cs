using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;

namespace Rendering.Accel;

public sealed partial class PreparedScene
{
  /// <summary>
  /// State of one closest-hit query. It holds no object reference (a list member's winning hit travels beside it),
  /// so a query on the stack is not zeroed per ray: <see cref="Start"/> sets every field read before it is written.
  /// </summary>
  struct Query
  {
    public double Len2;
    /// <summary>Pruning bound: min(EntryT, InsideT).</summary>
    public double BestT;

    // The first entry over members that start outside.
    public double EntryT;
    public int BestIndex;
    /// <summary>Leaf of a CSG member's record (-1: the member's own solid).</summary>
    public int BestLeaf;

    // The one member the ray starts inside (-1: none) and its first valid record, an exit.
    public int InsideIndex;
    public int InsideLeaf;
    public double InsideT;

    /// <summary>
    /// With a member the ray starts inside: another member is entered before that member's exit (or at the same T), so
    /// the union rule does not decide the first record and the faithful path does.
    /// </summary>
    public readonly bool EnteredBeforeExit => BestIndex != int.MaxValue && EntryT <= InsideT;

    // Shadow queries: stop at the first blocker (Found), then only members that may contain the origin are visited.
    public bool Any;
    public bool Found;
    /// <summary>Just above the smallest accepted t: members whose boxes start beyond it cannot contain the origin.</summary>
    public double AnyBound;

    // Three record slots: the entry's, the inside member's and a free one. A kernel writes its record straight into
    // the free slot; a record that wins trades slots with the free one, so no record is copied.
    Records slots;
    int bestSlot, insideSlot, freeSlot;

    [InlineArray(3)]
    struct Records
    {
      SolidRecord first;
    }

    /// <summary>A fresh query (<c>Unsafe.SkipInit</c> first): the fields read before they are written.</summary>
    public void Start(double len2, double bound)
    {
      Len2 = len2;
      BestT = bound;
      EntryT = bound;
      BestIndex = int.MaxValue;
      BestLeaf = -1;
      InsideIndex = -1;
      InsideLeaf = -1;
      InsideT = 0.0;
      Any = false;
      Found = false;
      AnyBound = 0.0;
      bestSlot = 0;
      insideSlot = 1;
      freeSlot = 2;
    }

    /// <summary>The slot a kernel writes its record into.</summary>
    [UnscopedRef]
    public ref SolidRecord Free => ref Unsafe.Add(ref Unsafe.As<Records, SolidRecord>(ref slots), freeSlot);

    /// <summary>The entry's record (valid when <see cref="BestIndex"/> is set and the entry is not a list hit).</summary>
    [UnscopedRef]
    public ref SolidRecord BestHit => ref Unsafe.Add(ref Unsafe.As<Records, SolidRecord>(ref slots), bestSlot);

    /// <summary>The inside member's record (valid when <see cref="InsideIndex"/> ≥ 0).</summary>
    [UnscopedRef]
    public ref SolidRecord InsideHit => ref Unsafe.Add(ref Unsafe.As<Records, SolidRecord>(ref slots), insideSlot);

    /// <summary>The free slot's record becomes the entry's.</summary>
    public void TakeBest() => (bestSlot, freeSlot) = (freeSlot, bestSlot);

    /// <summary>The free slot's record becomes the inside member's.</summary>
    public void TakeInside() => (insideSlot, freeSlot) = (freeSlot, insideSlot);
  }
}
