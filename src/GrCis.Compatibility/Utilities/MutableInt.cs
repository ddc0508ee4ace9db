namespace Utilities;

/// <summary>A mutable int (GrCis): <c>counts[key]++</c> on a dictionary of these needs one look-up.</summary>
public class MutableInt : Mutable<int>
{
  public MutableInt(int val = 0) : base(val)
  {
  }

  public static MutableInt operator ++(MutableInt mi)
  {
    mi.value++;
    return mi;
  }

  /// <summary>Sets the bits of <paramref name="m"/> in place.</summary>
  public static MutableInt operator |(MutableInt mi, int m)
  {
    mi.value |= m;
    return mi;
  }

  /// <summary>Sets the bits of <paramref name="mask"/>; returns the new value.</summary>
  public int Or(int mask) => value |= mask;
}
