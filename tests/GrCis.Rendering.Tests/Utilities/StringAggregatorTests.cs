using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class StringAggregatorTests
{
  [Fact]
  public void Keys_are_grouped_by_the_part_before_the_separator()
  {
    IAggregator<string> byName = new StringAggregatorFirstChar();
    Assert.Equal("Sphere", byName.ReduceKey("Sphere(3)"));
    Assert.Equal("Cube", byName.ReduceKey("Cube"));
    Assert.Null(byName.ReduceKey(null!));
    Assert.Equal(0, byName.Compare("Sphere(3)", "Sphere(7)"));
    Assert.True(byName.Compare("Cube(9)", "Sphere(1)") < 0);

    var counts = new SortedDictionary<string, int>(byName);
    foreach (string k in new[] { "Sphere(1)", "Cube(2)", "Sphere(5)" })
      counts[k] = counts.TryGetValue(k, out int n) ? n + 1 : 1;
    Assert.Equal(new[] { 1, 2 }, counts.Values);

    Assert.Equal("a", new StringAggregatorFirstChar(':').ReduceKey("a:b:c"));
  }
}
