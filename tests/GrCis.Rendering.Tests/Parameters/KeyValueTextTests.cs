using System.Collections.Generic;
using Rendering;
using Utilities;

namespace GrCis.Rendering.Tests.Parameters;

/// <summary>
/// The core's parser (used by the script host) and GrCis's Util (used by scripts, in GrCis.Compatibility)
/// must read a parameter or context value the same way; Util's own rules are tested in UtilTests.
/// </summary>
public class KeyValueTextTests
{
  [Theory]
  [InlineData("n=4, r = 0.5 ,shadows, name=a b", "n", "4")]
  [InlineData("n=4, n=7", "n", "7")]
  [InlineData(" =3, shadows", "shadows", "")]
  public void Parse_gives_the_same_map_as_Util_ParseKeyValueList(string text, string key, string value)
  {
    Dictionary<string, string> core = KeyValueText.Parse(text);
    Assert.Equal(Util.ParseKeyValueList(text), core);
    Assert.Equal(value, core[key]);
  }

  [Theory]
  [InlineData("1.5")]
  [InlineData("4")]
  [InlineData("1,5")]
  [InlineData("yes")]
  [InlineData("off")]
  [InlineData("")]
  [InlineData("x")]
  public void Param_values_read_alike_in_the_host_and_in_scripts(string value)
  {
    var rec = new Dictionary<string, string> { ["k"] = value };
    double d1 = -1.0, d2 = -1.0;
    int i1 = -1, i2 = -1;
    bool b1 = false, b2 = false;
    Assert.Equal(Util.TryParse(rec, "k", ref d1), KeyValueText.TryParse(rec, "k", ref d2));
    Assert.Equal(Util.TryParse(rec, "k", ref i1), KeyValueText.TryParse(rec, "k", ref i2));
    Assert.Equal(Util.TryParse(rec, "k", ref b1), KeyValueText.TryParse(rec, "k", ref b2));
    Assert.Equal((d1, i1, b1), (d2, i2, b2));
  }

  [Fact]
  public void Context_number_that_is_not_whole_is_no_int_but_is_a_double()
  {
    var ctx = new Dictionary<string, object> { [PropertyName.CTX_FPS] = 12.5 };
    int i = 25;
    double d = 25.0;
    Assert.False(KeyValueText.TryParse(ctx, PropertyName.CTX_FPS, ref i));
    Assert.Equal(25, i);
    Assert.True(KeyValueText.TryParse(ctx, PropertyName.CTX_FPS, ref d));
    Assert.Equal(12.5, d);
  }
}
