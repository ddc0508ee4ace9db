using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// Where one pixel's primary ray hit (a point of <see cref="HitPointCloud"/>): the pixel, the world point, the pixel's
/// linear colour and the solid hit (a leaf of the scene graph: for a CSG result, the operand whose surface it is).
/// </summary>
public readonly record struct HitPoint(int X, int Y, Vector3d Position, Vector3d Color, ISolid? Solid);
