using System.Linq;
using System.Threading.Tasks;

namespace GrCis.Editing.Tests;

public sealed class CompletionTests(AssistantFixture fixture) : IClassFixture<AssistantFixture>
{
  readonly ScriptAssistant assistant = fixture.Assistant;

  [Fact]
  public async Task Scene_dot_offers_the_scenes_members_with_their_documentation()
  {
    const string source = "scene.";
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    string[] labels = result.Items.Select(i => i.Label).ToArray();
    Assert.Contains("Intersectable", labels);
    Assert.Contains("Camera", labels);
    Assert.Contains("Sources", labels);
    Assert.Contains("BackgroundColor", labels);
    Assert.DoesNotContain("Sphere", labels); // members only, not the types in scope
    Assert.Equal(source.Length, result.From);
    CompletionEntry? camera = await assistant.DescribeAsync(source, source.Length, "Camera");
    Assert.NotNull(camera);
    Assert.Equal("property", camera.Kind);
    Assert.Contains("ICamera", camera.Detail);
  }

  [Fact]
  public async Task The_first_entry_comes_described_and_the_rest_on_request()
  {
    const string source = "scene.Intersectable = new PhongMat";
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    Assert.Equal("PhongMaterial", result.Items[0].Label);
    Assert.Contains("Phong material", result.Items[0].Documentation);
    Assert.All(result.Items.Skip(ScriptAssistant.DescribedCompletions), i => Assert.Null(i.Detail));
    Assert.Null(await assistant.DescribeAsync(source, source.Length, "NoSuchEntry"));
  }

  [Theory]
  [InlineData("sc.")]          // 2018's name of the scene
  [InlineData("context.")]     // the dictionary
  public async Task Every_years_globals_are_typed(string source)
  {
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    Assert.NotEmpty(result.Items);
    Assert.Contains(result.Items, i => i.Label is "Intersectable" or "ContainsKey");
  }

  [Fact]
  public async Task A_partly_typed_name_lists_the_matching_types_best_first_and_replaces_the_word()
  {
    const string source = "scene.Intersectable = new Pho";
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    Assert.Equal("PhongMaterial", result.Items[0].Label);
    Assert.Equal(source.Length - 3, result.From);
    Assert.Equal(source.Length, result.To);
    Assert.All(result.Items, i => Assert.True(i.Label.Contains("Pho", System.StringComparison.OrdinalIgnoreCase) || WordStarts(i.Label, "Pho"), i.Label));
  }

  [Fact]
  public async Task Word_starts_find_a_type_by_its_capitals()
  {
    const string source = "var m = new PhMat";
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    Assert.Contains(result.Items.Take(5), i => i.Label == "PhongMaterial");
  }

  [Fact]
  public async Task Locals_of_the_script_are_offered()
  {
    const string source = "double radiusOfBall = 1.0;\nvar s = new Sphere(); s.SetAttribute(\"x\", radiusOf";
    CompletionResult result = await assistant.CompleteAsync(source, source.Length);
    Assert.Equal("radiusOfBall", result.Items[0].Label);
    Assert.Equal("field", result.Items[0].Kind); // a script's top-level variable is a field of its class
  }

  // The next line starts with a name and a dot (most lines of a script): the parser read the word and that line as one
  // declaration (scene.C root.InsertChild(...), a method), and the lists came out empty.
  [Theory]
  [InlineData("CSGInnerNode root = new CSGInnerNode(SetOperation.Union);\nscene.C", "Camera")]
  [InlineData("CSGInnerNode root = new CSGInnerNode(SetOperation.Union);\nMT.r", "rnd")]
  [InlineData("CSGInnerNode root = new CSGInnerNode(SetOperation.Union);\nroot.Ins", "InsertChild")]
  [InlineData("CSGInnerNode root = new CSGInnerNode(SetOperation.Union);\nsc", "scene")]
  [InlineData("void Build(CSGInnerNode root)\n{\n  root.Ins", "InsertChild")]
  public async Task A_partial_name_above_a_line_starting_with_a_name_and_a_dot_lists_what_it_lists_at_the_end(string typed, string expected)
  {
    string next = typed.StartsWith("void", System.StringComparison.Ordinal) ? "\n  root.InsertChild(new Sphere(), Matrix4d.Identity);\n}" : "\nroot.InsertChild(new Sphere(), Matrix4d.Identity);";
    CompletionResult alone = await assistant.CompleteAsync(typed + (typed.StartsWith("void", System.StringComparison.Ordinal) ? "\n}" : ""), typed.Length, described: 0);
    CompletionResult above = await assistant.CompleteAsync(typed + next, typed.Length, described: 0);
    Assert.Contains(alone.Items, i => i.Label == expected);
    Assert.Equal(alone.Items.Select(i => i.Label), above.Items.Select(i => i.Label));
    Assert.Equal((alone.From, alone.To), (above.From, above.To));
  }

  [Fact]
  public async Task Inside_context_brackets_the_context_keys_come_first()
  {
    const string typed = "context[Pr";
    CompletionResult result = await assistant.CompleteAsync(typed + "\nscene.Intersectable = null;", typed.Length, described: 2);
    Assert.Equal("PropertyName", result.Items[0].Label);
    Assert.Equal("PropertyName.CTX_TOOLTIP", result.Items[1].Label); // what a script sets first
    Assert.Contains("ToolTip", result.Items[1].Detail);
    Assert.Contains("help text", result.Items[1].Documentation);
    Assert.Equal(typed.Length - 2, result.From);

    const string empty = "context[";
    CompletionResult all = await assistant.CompleteAsync(empty, empty.Length, described: 0);
    Assert.Equal("PropertyName", all.Items[0].Label);
    Assert.All(all.Items.Skip(1).Take(14), i => Assert.StartsWith("PropertyName.CTX_", i.Label));

    const string member = "context[PropertyName.CTX_TOOLTIP] = \"\";\ncontext[PropertyName.";
    CompletionResult keys = await assistant.CompleteAsync(member, member.Length, described: 0);
    Assert.Equal("CTX_WIDTH", keys.Items[0].Label); // the tooltip is set already
    CompletionEntry? described = await assistant.DescribeAsync(empty, empty.Length, "PropertyName.CTX_WIDTH");
    Assert.Contains("image width", described?.Documentation);
  }

  [Fact]
  public async Task A_position_outside_the_text_is_refused()
  {
    await Assert.ThrowsAsync<System.ArgumentOutOfRangeException>(() => assistant.CompleteAsync("scene.", 7));
  }

  static bool WordStarts(string label, string typed) =>
    string.Concat(label.Where(char.IsUpper)).StartsWith(typed[..1], System.StringComparison.Ordinal);
}
