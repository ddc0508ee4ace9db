namespace GrCis.Editing.Tests;

public sealed class CompletionRankingTests
{
  [Theory]
  [InlineData("PhongMaterial", "", 0)]
  [InlineData("PhongMaterial", "Pho", 0)]
  [InlineData("PhongMaterial", "pho", 1)]
  [InlineData("PhongMaterial", "PM", 2)]
  [InlineData("PhongMaterial", "pm", 2)]
  [InlineData("PhongMaterial", "PhMat", 2)]
  [InlineData("PhongMaterial", "PhX", -1)]
  [InlineData("PhongMaterial", "Mat", 2)]
  [InlineData("PhongMaterial", "ater", 3)]
  [InlineData("PhongMaterial", "xyz", -1)]
  [InlineData("CTX_WIDTH", "CW", 2)]
  public void Entries_rank_by_how_the_typed_word_matches(string name, string typed, int rank) =>
    Assert.Equal(rank, CompletionRanking.Rank(name, typed));
}
