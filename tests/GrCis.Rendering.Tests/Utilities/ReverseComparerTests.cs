using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class ReverseComparerTests
{
  [Fact]
  public void Sorts_from_the_largest_down_with_nulls_last()
  {
    var numbers = new List<int> { 3, 9, -1, 4 };
    numbers.Sort(new ReverseComparer<int>());
    Assert.Equal(new[] { 9, 4, 3, -1 }, numbers);

    var words = new List<string> { "b", null!, "c", "a" };
    words.Sort(new ReverseComparer<string>());
    Assert.Equal(new[] { "c", "b", "a", null }, words);
  }
}
