namespace Rendering;

/// <summary>CSG set operations of <see cref="CSGInnerNode"/>.</summary>
public enum SetOperation
{
  Union,
  Intersection,
  Difference,
  Xor,
}
