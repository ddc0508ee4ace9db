namespace Utilities;

/// <summary>A mutable float (GrCis).</summary>
public class MutableFloat : Mutable<float>
{
  public MutableFloat(float val) : base(val)
  {
  }
}
