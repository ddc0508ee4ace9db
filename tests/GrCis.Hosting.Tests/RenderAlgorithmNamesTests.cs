namespace GrCis.Hosting.Tests;

/// <summary>The algorithm names every front end accepts (<c>--algorithm</c>, the studio's <c>algorithm</c> field).</summary>
public class RenderAlgorithmNamesTests
{
  [Theory]
  [InlineData("raytracing", RenderAlgorithm.RayTracing)]
  [InlineData("distributed", RenderAlgorithm.Distributed)]
  [InlineData("path", RenderAlgorithm.Path)]
  public void Each_name_parses_to_its_algorithm_and_back(string name, RenderAlgorithm algorithm)
  {
    Assert.True(RenderAlgorithmNames.TryParse(name, out RenderAlgorithm parsed));
    Assert.Equal(algorithm, parsed);
    Assert.Equal(name, RenderAlgorithmNames.Name(algorithm));
    Assert.Contains(name, RenderAlgorithmNames.All);
  }

  [Theory]
  [InlineData(null)]
  [InlineData("")]
  [InlineData("Path")]
  [InlineData("RayTracing")]
  [InlineData("radiosity")]
  public void Anything_else_is_not_a_name(string? name) => Assert.False(RenderAlgorithmNames.TryParse(name, out _));

  [Fact]
  public void Every_algorithm_has_a_name() =>
    Assert.Equal(System.Enum.GetValues<RenderAlgorithm>().Length, RenderAlgorithmNames.All.Count);
}
