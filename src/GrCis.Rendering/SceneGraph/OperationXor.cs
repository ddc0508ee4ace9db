namespace Rendering;

/// <summary>Inside the result when inside exactly one operand.</summary>
public class OperationXor : Operation
{
  /// <inheritdoc/>
  public override bool Result(bool x, bool y) => x ^ y;
}
