namespace GrCis.Cli.Tests;

/// <summary>A mistyped command or option gets a "did you mean" (issue 39), as a mistyped scene name does.</summary>
public class TypoSuggestionTests
{
  [Theory]
  [InlineData(new[] { "rendr" }, "unknown command 'rendr': did you mean 'render'? (see 'grcis --help')")]
  [InlineData(new[] { "animtae", "x.cs" }, "unknown command 'animtae': did you mean 'animate'? (see 'grcis --help')")]
  [InlineData(new[] { "render", "--sise", "320x240" }, "unknown option '--sise': did you mean '--size'? (see 'grcis render --help')")]
  [InlineData(new[] { "render", "Toroids", "--sise", "320x240" }, "unknown option '--sise': did you mean '--size'? (see 'grcis render --help')")]
  [InlineData(new[] { "render", "--sise" }, "unknown option '--sise': did you mean '--size'? (see 'grcis render --help')")]
  [InlineData(new[] { "render", "--no-shadow" }, "unknown option '--no-shadow': did you mean '--no-shadows'? (see 'grcis render --help')")]
  [InlineData(new[] { "render", "--seeds", "3" }, "unknown option '--seeds': did you mean '--seed'? (see 'grcis render --help')")]
  [InlineData(new[] { "animate", "x.cs", "--fsp", "12" }, "unknown option '--fsp': did you mean '--fps'? (see 'grcis animate --help')")]
  public void A_close_name_is_suggested_and_nothing_runs(string[] args, string message)
  {
    using var tmp = new TempDirectory();
    CliRun run = CliRun.Of(tmp.Path, args);
    Assert.Equal(2, run.ExitCode);
    Assert.Equal("grcis: error: " + message, Assert.Single(run.ErrorLines));
    Assert.Empty(tmp.AllFiles());
  }

  [Fact]
  public void Values_and_far_words_get_no_guess()
  {
    using var tmp = new TempDirectory();
    // A value that looks like an option is the option's value (here a malformed size, reported as such).
    CliRun value = CliRun.Of(tmp.Path, "render", "--size", "-seed");
    Assert.Equal(2, value.ExitCode);
    Assert.DoesNotContain("did you mean", value.Error, System.StringComparison.Ordinal);
    // Nothing close: the parser's own message.
    CliRun far = CliRun.Of(tmp.Path, "xyzzy");
    Assert.Equal(2, far.ExitCode);
    Assert.DoesNotContain("did you mean", far.Error, System.StringComparison.Ordinal);
  }

  [Theory]
  [InlineData("ab", "ba", 1)]
  [InlineData("rendr", "render", 1)]
  [InlineData("sise", "size", 1)]
  [InlineData("animtae", "animate", 1)]
  [InlineData("kitten", "sitting", 3)]
  public void Distance_counts_a_swap_as_one_edit(string a, string b, int expected) =>
    Assert.Equal(expected, TypoSuggestions.Distance(a, b));

  [Fact]
  public void Short_names_are_not_guessed() =>
    Assert.Null(TypoSuggestions.Closest("-x", new[] { "-o", "--output", "-s", "--size" }));
}
