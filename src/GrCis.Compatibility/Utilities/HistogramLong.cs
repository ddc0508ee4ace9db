namespace Utilities;

/// <summary>A histogram of longs in bins of <see cref="BinnedHistogram{T}.BinSize"/> (GrCis).</summary>
public class HistogramLong : BinnedHistogram<long>
{
  public HistogramLong(long binSize = 1) : base(binSize)
  {
  }
}
