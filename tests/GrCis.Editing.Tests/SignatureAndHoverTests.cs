using System.Linq;
using System.Threading.Tasks;

namespace GrCis.Editing.Tests;

public sealed class SignatureAndHoverTests(AssistantFixture fixture) : IClassFixture<AssistantFixture>
{
  readonly ScriptAssistant assistant = fixture.Assistant;

  [Fact]
  public async Task New_with_an_open_parenthesis_shows_the_constructors()
  {
    const string source = "var m = new PhongMaterial(";
    SignatureHelp? help = await assistant.SignatureAsync(source, source.Length);
    Assert.NotNull(help);
    Assert.All(help.Signatures, s => Assert.StartsWith("PhongMaterial(", s.Label));
    Assert.Contains(help.Signatures, s => s.Parameters.Count >= 4);
    Assert.Equal(0, help.ActiveParameter);
  }

  [Fact]
  public async Task The_argument_after_two_commas_is_the_third_and_nested_calls_do_not_count()
  {
    const string source = "var m = new PhongMaterial(new double[] { 1, 0, 0 }, System.Math.Max(0.1, 0.2), ";
    SignatureHelp? help = await assistant.SignatureAsync(source, source.Length);
    Assert.NotNull(help);
    Assert.Equal(2, help.ActiveParameter);
    Assert.True(help.Signatures[help.Active].Parameters.Count > 2, help.Signatures[help.Active].Label);
  }

  [Fact]
  public async Task In_a_call_being_edited_the_arguments_after_the_caret_choose_the_overload_not_the_copy_constructor()
  {
    // Unfinished (no closing parenthesis), so nothing binds: before, the first overload with room for one argument
    // was shown, PhongMaterial(PhongMaterial), though the argument after the caret is a double[].
    const string source = "var m = new PhongMaterial(new double[] { 1, 0, 0 }, 0.1, 0.6\nscene.Intersectable = null;";
    int caret = source.IndexOf('(') + 1;
    SignatureHelp? help = await assistant.SignatureAsync(source, caret);
    Assert.NotNull(help);
    Assert.Equal(0, help.ActiveParameter);
    Assert.StartsWith("PhongMaterial(double[]", help.Signatures[help.Active].Label);
  }

  [Fact]
  public async Task Inside_a_method_call_the_method_groups_overloads_are_shown_with_their_docs()
  {
    const string source = "double x = System.Math.Max(1.0, ";
    SignatureHelp? help = await assistant.SignatureAsync(source, source.Length);
    Assert.NotNull(help);
    Assert.True(help.Signatures.Count > 5);
    Assert.Equal(1, help.ActiveParameter);
    Assert.Contains("double", help.Signatures[help.Active].Label);
  }

  [Fact]
  public async Task Outside_any_call_there_is_no_signature()
  {
    const string source = "var m = new PhongMaterial(); m";
    Assert.Null(await assistant.SignatureAsync(source, source.Length));
  }

  [Fact]
  public async Task Hovering_PhongMaterial_shows_its_doc_comment()
  {
    const string source = "PhongMaterial m = null;";
    int at = source.IndexOf("PhongMaterial", System.StringComparison.Ordinal) + 3;
    HoverInfo? hover = await assistant.HoverAsync(source, at);
    Assert.NotNull(hover);
    Assert.Contains("PhongMaterial", hover.Text);
    Assert.NotNull(hover.Documentation);
    Assert.Contains("Phong material", hover.Documentation);
    Assert.Equal(source.IndexOf("PhongMaterial", System.StringComparison.Ordinal), hover.From);
  }

  [Fact]
  public async Task Hovering_a_math_type_shows_its_doc_comment_from_the_math_assembly()
  {
    const string source = "Vector3d v = Vector3d.UnitX;";
    HoverInfo? hover = await assistant.HoverAsync(source, 3);
    Assert.NotNull(hover);
    Assert.Contains("Vector3d", hover.Text);
    Assert.NotNull(hover.Documentation);
    Assert.Contains("3D vector of doubles", hover.Documentation);
  }

  /// <summary>
  /// The framework's own members are documented from the SDK's reference pack; System.Private.CoreLib's types from the
  /// files of the contracts that expose them (System.Runtime, System.Collections, System.Console).
  /// </summary>
  [Theory]
  [InlineData("double r = Math.Sqrt(2.0);", "Sqrt", "Returns the square root of a specified number.")]
  [InlineData("var l = new List<int>(); l.Add(1);", "Add", "Adds an object to the end of the")]
  [InlineData("Console.WriteLine(\"x\");", "WriteLine", "followed by the current line terminator, to the standard output stream.")]
  public async Task Hovering_a_framework_member_shows_its_doc_comment_from_the_reference_pack(string source, string member, string expected)
  {
    HoverInfo? hover = await assistant.HoverAsync(source, source.IndexOf(member, System.StringComparison.Ordinal) + 1);
    Assert.NotNull(hover);
    Assert.Contains(member, hover.Text);
    Assert.NotNull(hover.Documentation);
    Assert.Contains(expected, hover.Documentation);
  }

  [Fact]
  public async Task Hovering_a_constructor_call_shows_the_constructors_doc_comment()
  {
    const string source = "var m = new PhongMaterial();";
    HoverInfo? hover = await assistant.HoverAsync(source, source.IndexOf("Phong", System.StringComparison.Ordinal) + 2);
    Assert.NotNull(hover);
    Assert.Contains("PhongMaterial()", hover.Text);
    Assert.Contains("default material", hover.Documentation);
  }

  [Fact]
  public async Task Hovering_a_global_shows_its_type()
  {
    const string source = "scene.Camera = null;";
    HoverInfo? hover = await assistant.HoverAsync(source, 2);
    Assert.NotNull(hover);
    Assert.Contains("IRayScene", hover.Text);
  }

  [Fact]
  public async Task Hovering_white_space_shows_nothing()
  {
    Assert.Null(await assistant.HoverAsync("  \n  ", 1));
  }
}
