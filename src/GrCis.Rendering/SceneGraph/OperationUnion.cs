namespace Rendering;

/// <summary>Inside the result when inside either operand.</summary>
public class OperationUnion : Operation
{
  /// <inheritdoc/>
  public override bool Result(bool x, bool y) => x || y;
}
