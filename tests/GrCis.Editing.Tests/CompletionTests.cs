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

  [Fact]
  public async Task A_position_outside_the_text_is_refused()
  {
    await Assert.ThrowsAsync<System.ArgumentOutOfRangeException>(() => assistant.CompleteAsync("scene.", 7));
  }

  static bool WordStarts(string label, string typed) =>
    string.Concat(label.Where(char.IsUpper)).StartsWith(typed[..1], System.StringComparison.Ordinal);
}
