using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Custom shading hook (attribute <see cref="PropertyName.RECURSION"/>): given the hit, the ray direction
/// and the importance, returns a hash and what the tracer should add and trace further.
/// </summary>
public delegate long RecursionFunction(Intersection i, Vector3d dir, double importance, out RayRecursion rr);
