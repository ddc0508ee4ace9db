using System.Collections.Generic;
using System.Linq;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's key–object relation: sets of object ids by key id, its inverse, and the id resolvers.</summary>
public class KeyObjectMapsTests
{
  sealed class Exposed : KeyObjectMaps<int, string>
  {
    public Exposed(GetCheckObjectDelegate<int>? getKey = null) : base(getKey) { }
    public int KeyOf(string id) => GetKey(id);
    public string ObjectOf(string id) => GetObject(id);
  }

  [Fact]
  public void Sets_are_built_counted_and_queried()
  {
    var maps = new KeyObjectMaps<int, string>();
    Assert.True(maps.AddObject("red", "ball"));
    Assert.False(maps.AddObject("red", "ball"));
    Assert.False(maps.AddObject(null!, "ball"));
    maps.AddObjects("red", new[] { "cube", "ball" });
    maps.AddObjects("blue", new[] { "cube" });
    maps.AddObjects("green", Enumerable.Empty<string>());   // nothing: no empty set is made

    Assert.Equal(2, maps.Count);
    Assert.Equal(2, maps.Card("red"));
    Assert.Equal(0, maps.Card("green"));
    Assert.Equal(0, maps.Card(null!));
    Assert.Equal(new[] { "blue", "red" }, maps.AllKeyIds.OrderBy(s => s));
    Assert.Equal(new[] { "ball", "cube" }, maps.AllObjectIds.OrderBy(s => s));
    Assert.Equal(new[] { "cube" }, maps.ObjectIds("blue"));
    Assert.Empty(maps.ObjectIds("nothing"));
    Assert.True(maps.Contains("red", "cube"));
    Assert.False(maps.Contains("blue", "ball"));

    KeyObjectMaps<string, int> inverse = maps.Inverse();
    Assert.Equal(new[] { "blue", "red" }, inverse.ObjectIds("cube").OrderBy(s => s));
    Assert.True(inverse.Contains("ball", "red"));
    Assert.Equal(2, inverse.Count);
  }

  [Fact]
  public void Unset_resolvers_answer_default_and_given_ones_are_used()
  {
    var plain = new Exposed();
    Assert.Equal(0, plain.KeyOf("7"));
    Assert.Null(plain.ObjectOf("x"));

    var parsing = new Exposed(id => int.Parse(id));
    Assert.Equal(7, parsing.KeyOf("7"));
    parsing.GetObject = id => id.ToUpperInvariant();
    Assert.Equal("X", parsing.ObjectOf("x"));
  }
}
