namespace GrCis.Scripting.Tests;

public class ScriptParametersTests
{
  [Fact]
  public void Getters_return_values_or_defaults()
  {
    var p = new ScriptParameters("n=1.5, depth=3, mat=Glass, rc");
    Assert.Equal(1.5, p.GetDouble("n", 1.6));
    Assert.Equal(3, p.GetInt("depth", 5));
    Assert.Equal(3L, p.GetLong("depth", 5));
    Assert.True(p.GetBool("rc", false));
    Assert.Equal("glass", p.GetChoice("mat", "diffuse", "diffuse", "mirror", "glass"));
    Assert.Equal(7.0, p.GetDouble("missing", 7.0));
    Assert.Equal("x", p.GetString("missing", "x"));
    Assert.True(p.Contains("rc"));
  }

  [Fact]
  public void Wrong_values_throw_a_message_naming_key_value_and_expectation()
  {
    var p = new ScriptParameters("n=abc, depth=2.5, rc=maybe, mat=wood");
    Assert.Equal("parameter 'n' has the value 'abc', expected a number (e.g. 1.5)",
                 Assert.Throws<ScriptParameterException>(() => p.GetDouble("n", 1.6)).Message);
    Assert.Equal("parameter 'depth' has the value '2.5', expected a whole number (e.g. 4)",
                 Assert.Throws<ScriptParameterException>(() => p.GetInt("depth", 5)).Message);
    Assert.Contains("yes/no", Assert.Throws<ScriptParameterException>(() => p.GetBool("rc", false)).Message);
    Assert.Equal("parameter 'mat' has the value 'wood', expected one of diffuse, glass",
                 Assert.Throws<ScriptParameterException>(() => p.GetChoice("mat", "diffuse", "diffuse", "glass")).Message);
  }
}
