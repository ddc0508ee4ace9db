using System.Collections.Generic;

namespace Rendering.Accel;

/// <summary>What the preparation decided for one member of a scene (or one leaf of a member's CSG kernel).</summary>
/// <param name="Node">The member's scene node.</param>
/// <param name="Kernel">What answers its rays.</param>
/// <param name="Closed">Records only inside its world box: it may live in the BVH (false: tested for every ray).</param>
/// <param name="Completion">How its hits are completed when only the library's shading reads them.</param>
/// <param name="LibraryPhong">Its hits are shaded by the library's Phong model and material, with no recursion function
/// (<see cref="LibraryTypes.IsLibraryPhong"/>); false as well when its attributes are looked up per hit (a list member).</param>
/// <param name="Leaves">The leaves of a <see cref="MemberKernel.Csg"/> member, in depth-first order (empty otherwise).</param>
internal readonly record struct MemberCapability(
  IIntersectable Node, MemberKernel Kernel, bool Closed, HitCompletion Completion, bool LibraryPhong, IReadOnlyList<MemberCapability> Leaves);
