using System;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's Quantiles: mean, variance and linearly interpolated quantiles of a known list.</summary>
public class QuantilesTests
{
  // Sorted: 1 1 2 3 4 5 6 9; sum 31, sum of squares 173.
  static readonly int[] sample = { 3, 1, 4, 1, 5, 9, 2, 6 };

  static Quantiles<int> Sample()
  {
    var q = new Quantiles<int>();
    q.AddRange(sample);
    return q;
  }

  [Theory]
  [InlineData(1, 0, 1.0)]
  [InlineData(4, 1, 1.75)]
  [InlineData(2, 1, 3.5)]
  [InlineData(4, 3, 5.25)]
  [InlineData(10, 9, 6.9)]
  [InlineData(1, 1, 9.0)]
  [InlineData(4, 7, 9.0)]
  [InlineData(4, -1, 1.0)]
  public void Quantile_interpolates_between_sorted_values(int q, int i, double expected) =>
    Assert.Equal(expected, Sample().Quantile(q, i), 12);

  [Fact]
  public void Mean_and_variances_of_the_known_list()
  {
    Quantiles<int> q = Sample();
    Assert.Equal(3.875, q.Mean, 12);
    Assert.Equal(52.875 / 8, q.Variance, 12);
    Assert.Equal(52.875 / 7, q.VarianceBessel, 12);
    Assert.Equal(1.0, q.Min);
    Assert.Equal(9.0, q.Max);
    Assert.Equal(3.5, q.Median);
    Assert.Equal(q.Quantile(4, 1), q.Quartile(1));
  }

  [Fact]
  public void Empty_and_single_value_statistics()
  {
    var q = new Quantiles<double>();
    Assert.True(double.IsNaN(q.Mean) && double.IsNaN(q.Variance) && double.IsNaN(q.Median));
    q.Add(2.5);
    Assert.Equal(2.5, q.Median);
    Assert.Equal(0.0, q.Variance);
    Assert.True(double.IsNaN(q.VarianceBessel));
  }

  [Fact]
  public void Without_stored_values_only_mean_and_variance_exist()
  {
    var q = new Quantiles<float>(quantiles: false, capacity: 100);
    q.AddRange(new[] { 1f, 2f, 3f, 6f });
    Assert.Empty(q);
    Assert.Equal(3.0, q.Mean, 12);
    Assert.Equal(3.5, q.Variance, 12);
    Assert.True(double.IsNaN(q.Median));
    q.Remove(6f);
    Assert.Equal(2.0, q.Mean, 12);
  }

  [Fact]
  public void Removing_values_updates_the_statistics()
  {
    Quantiles<int> q = Sample();
    q.Remove(9);
    q.Remove(42);                       // not there: nothing changes
    Assert.Equal(22 / 7.0, q.Mean, 12);
    Assert.Equal(6.0, q.Max);
    q.RemoveAll(x => x == 1);
    Assert.Equal(2.0, q.Min);
    Assert.Equal(20 / 5.0, q.Mean, 12);
    q.RemoveRange(0, 2);                // the list is sorted now: 2 and 3 go
    Assert.Equal(new[] { 4, 5, 6 }, q.ToArray());
    Assert.Equal(5.0, q.Mean, 12);
    q.RemoveAt(10);
    Assert.Equal(3, q.Count);
    q.Clear();
    Assert.True(double.IsNaN(q.Mean));
  }

  [Fact]
  public void Inserting_and_replacing_values_updates_the_statistics()
  {
    var q = new Quantiles<long>();
    q.AddRange(new[] { 10L, 20L });
    q.InsertRange(1, new[] { 1L, 2L });
    Assert.Equal(new[] { 10L, 1L, 2L, 20L }, q.ToArray());
    q.Insert(0, 7L);
    q[4] = 30L;
    Assert.Equal(50 / 5.0, q.Mean, 12);
    Assert.Equal(30.0, q.Max);
    Assert.Equal(7.0, q.Median);
  }
}
