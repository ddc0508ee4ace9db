namespace Rendering;

/// <summary>Inside the result when inside exactly one operand.</summary>
public class OperationXor : Operation
{
  public override bool Result(bool x, bool y) => x ^ y;
}
