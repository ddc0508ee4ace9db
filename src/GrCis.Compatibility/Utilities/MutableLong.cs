namespace Utilities;

/// <summary>A mutable long (GrCis).</summary>
public class MutableLong : Mutable<long>
{
  public MutableLong(long val = 0L) : base(val)
  {
  }

  public static MutableLong operator ++(MutableLong ml)
  {
    ml.value++;
    return ml;
  }
}
