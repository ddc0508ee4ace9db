using GrCis.Cli.Jobs;
using GrCis.Cli.SceneSources;
using GrCis.Hosting;

namespace GrCis.Cli.Tests;

public class ParsingTests
{
  [Theory]
  [InlineData("640x480", 640, 480)]
  [InlineData("1X1", 1, 1)]
  [InlineData(" 1280x720 ", 1280, 720)]
  public void Size_parses_width_x_height(string text, int w, int h) =>
    Assert.Equal(new ImageSize(w, h), ImageSize.Parse(text));

  [Theory]
  [InlineData("Sphere on the plane", "sphere-on-the-plane")]
  [InlineData("Hedgehog in the cage", "hedgehog-in-the-cage")]
  [InlineData("  ", "render")]
  public void Slug_is_lower_case_words_joined_by_dashes(string name, string slug) =>
    Assert.Equal(slug, Slug.Of(name));

  [Fact]
  public void Suggestions_prefer_close_names_and_ignore_unrelated_ones()
  {
    string[] known = { "Five balls", "Flags", "Sphere flake", "Sphere on the plane", "Two spheres" };
    Assert.Equal("Flags", NameSuggestions.Closest("Flgas", known)[0]);
    Assert.Equal("Sphere flake", NameSuggestions.Closest("sphereflak", known)[0]);
    Assert.Empty(NameSuggestions.Closest("qqqqqqqq", known));
  }

  [Theory]
  [InlineData(1, 1)]
  [InlineData(4, 4)]
  [InlineData(5, 9)]
  [InlineData(16, 16)]
  public void Samples_per_pixel_round_up_to_a_square_grid(int spp, int effective) =>
    Assert.Equal(effective, new RenderSettings { SamplesPerPixel = spp }.EffectiveSamplesPerPixel);
}
