namespace Rendering;

/// <summary>CSG set operations of <see cref="CSGInnerNode"/>.</summary>
public enum SetOperation
{
  /// <summary>Inside the result when inside either operand.</summary>
  Union,
  /// <summary>Inside the result when inside both operands.</summary>
  Intersection,
  /// <summary>Inside the result when inside the left operand but not the right one.</summary>
  Difference,
  /// <summary>Inside the result when inside exactly one operand.</summary>
  Xor,
}
