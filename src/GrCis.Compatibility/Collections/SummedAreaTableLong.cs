namespace MathSupport;

/// <summary>
/// GrCis's summed-area table: fill <see cref="table"/> with values, call <see cref="ComputeTable"/>,
/// then <see cref="Sum"/> gives the sum over any rectangle in constant time.
/// </summary>
public class SummedAreaTableLong
{
  public long[,]? table;

  public SummedAreaTableLong()
  {
  }

  public SummedAreaTableLong(int xres, int yres) => table = new long[xres, yres];

  /// <summary>Turns the values into prefix sums: table[x, y] = sum of the values at [0..x, 0..y].</summary>
  public void ComputeTable() => SummedArea.Compute(table!);

  /// <summary>Sum of the original values over [x1..x2] × [y1..y2] (inclusive).</summary>
  public long Sum(int x1, int x2, int y1, int y2) => SummedArea.Sum(table!, x1, x2, y1, y2);
}
