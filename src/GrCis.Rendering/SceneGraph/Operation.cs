namespace Rendering;

/// <summary>GrCis's set operation as an object: whether a point is inside the result, given whether it is inside each operand.</summary>
public abstract class Operation
{
  /// <summary>Whether a point is inside the result.</summary>
  /// <param name="x">The point is inside the left operand.</param>
  /// <param name="y">The point is inside the right operand.</param>
  public abstract bool Result(bool x, bool y);
}
