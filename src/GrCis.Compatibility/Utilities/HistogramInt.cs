namespace Utilities;

/// <summary>A histogram of ints in bins of <see cref="BinnedHistogram{T}.BinSize"/> (GrCis).</summary>
public class HistogramInt : BinnedHistogram<int>
{
  public HistogramInt(int binSize = 1) : base(binSize)
  {
  }
}
