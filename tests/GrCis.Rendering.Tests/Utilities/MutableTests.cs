using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class MutableTests
{
  [Fact]
  public void A_dictionary_of_mutable_ints_counts_in_place()
  {
    var counts = new Dictionary<string, MutableInt>();
    foreach (string w in new[] { "a", "b", "a", "a" })
    {
      if (!counts.TryGetValue(w, out MutableInt? c))
        counts[w] = c = new MutableInt();
      c++;
    }
    Assert.Equal(3, (int)counts["a"]);
    Assert.Equal(1, counts["b"].value);
  }

  [Fact]
  public void Inc_Or_and_the_operators_change_the_value_in_place_and_return_it()
  {
    var i = new MutableInt(5);
    MutableInt same = i | 8;
    Assert.Same(i, same);
    Assert.Equal(13, i.value);
    Assert.Equal(15, i.Or(2));
    Assert.Equal(20, i.Inc(5));

    var l = new MutableLong();
    l++;
    Assert.Equal(1L, (long)l);
    Assert.Equal(1L + 10_000_000_000L, l.Inc(10_000_000_000L));

    var f = new MutableFloat(0.5f);
    Assert.Equal(2.0f, f.Inc(1.5f));
    float plain = f;
    Assert.Equal(2.0f, plain);
    Assert.Equal("2", f.ToString());
  }
}
