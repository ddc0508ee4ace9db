namespace GrCis.Studio.Tests;

/// <summary>The browser tests run one class after another: two headless browsers rendering at once on a small machine
/// would make each wait for the other.</summary>
[CollectionDefinition(Name)]
public sealed class BrowserCollection
{
  public const string Name = "Browser";
}
