namespace GrCis.Cli.Tests;

/// <summary>
/// The test classes that pack the repository's projects (README's <c>dotnet pack GrCis.sln</c>, the portable packages
/// of <see cref="PackagesTests"/>) run one after the other: both write the tool's packaging files under the same
/// <c>obj/</c> and <c>bin/</c> folders (its tool settings among them), and a pack that reads the other's half-written
/// files makes a package without its entry point.
/// </summary>
[CollectionDefinition(Name)]
public sealed class RepositoryPacking
{
  public const string Name = "packs the repository";
}
