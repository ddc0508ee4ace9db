namespace Rendering;

/// <summary>Inside the result when inside the left operand but not the right.</summary>
public class OperationDifference : Operation
{
  /// <inheritdoc/>
  public override bool Result(bool x, bool y) => x && !y;
}
