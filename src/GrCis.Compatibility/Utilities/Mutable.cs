using System.Numerics;

namespace Utilities;

/// <summary>
/// A number that can be changed in place, e.g. as a dictionary value counted up without a second look-up
/// (GrCis's MutableInt, MutableLong and MutableFloat share this base).
/// </summary>
public abstract class Mutable<T> where T : INumber<T>
{
  public T value;

  protected Mutable(T val) => value = val;

  public static implicit operator T(Mutable<T> m) => m.value;

  /// <summary>Adds <paramref name="val"/>; returns the new value.</summary>
  public T Inc(T val) => value += val;

  public override string ToString() => value.ToString() ?? "";
}
