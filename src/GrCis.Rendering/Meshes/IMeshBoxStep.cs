using System.Runtime.Intrinsics;

namespace Rendering;

/// <summary>
/// A mesh walk's box test of one <see cref="MeshNode"/>'s eight boxes (a struct, so each walk is compiled once per kind
/// and the test inlined): the mask of the boxes the line crosses and, per box, an interval of line parameters that
/// contains the one the exact double slab test gives (floats, so near may be earlier and far later).
/// </summary>
internal interface IMeshBoxStep
{
  int Cross(ref readonly MeshNode n, out Vector256<float> near, out Vector256<float> far);
}
