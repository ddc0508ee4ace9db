using System.Net;
using System.Net.Http;
using System.Threading.Tasks;

namespace GrCis.Cli.Tests;

/// <summary>
/// <c>grcis studio</c> tells its address once the editor's code completion answers, so a page opened at once is not
/// seconds from its first completion (issue 39); before that it says on the error output that it is loading.
/// </summary>
public sealed class StudioWarmStartTests
{
  [Fact]
  public async Task The_address_comes_once_the_editor_is_ready()
  {
    using var dir = new TempDirectory();
    System.IO.File.Copy(RepoPaths.Script("TwoSpheres.cs"), dir.File("TwoSpheres.cs"));
    using var studio = new SupervisedStudio(dir.Path);
    // Asked without waiting: 204 when loaded, 503 while loading.
    using HttpResponseMessage ready = await studio.Client.GetAsync("api/editor/ready?wait=false");
    Assert.Equal(HttpStatusCode.NoContent, ready.StatusCode);
  }
}
