using System.Runtime.CompilerServices;

namespace Rendering.Accel;

/// <summary>
/// A traversal stack that lives in its method's frame. A <c>stackalloc</c> of more than a few elements is a dynamic
/// stack allocation, which makes the JIT give the whole method a variable frame and a stack-guard check on every
/// return; a fixed buffer of the same size costs nothing per call.
/// </summary>
[InlineArray(Capacity)]
internal struct WalkStack<T> where T : unmanaged
{
  /// <summary>Entries held (a four-wide walk pushes at most three more than it pops per level).</summary>
  public const int Capacity = 256;

  T first;
}
