namespace Rendering;

/// <summary>Inside the result when inside both operands.</summary>
public class OperationIntersection : Operation
{
  /// <inheritdoc/>
  public override bool Result(bool x, bool y) => x && y;
}
