namespace Rendering;

/// <summary>GrCis's set operation as an object: whether a point is inside the result, given whether it is inside each operand.</summary>
public abstract class Operation
{
  public abstract bool Result(bool x, bool y);
}
