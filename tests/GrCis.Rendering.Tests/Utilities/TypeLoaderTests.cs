using System.Linq;
using Rendering;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

public class TypeLoaderTests
{
  [Fact]
  public void GetTypesWithInterface_finds_implementations_but_not_the_interface()
  {
    var found = TypeLoader.GetTypesWithInterface<IAggregator<string>>().ToList();
    Assert.Contains(typeof(StringAggregatorFirstChar), found);
    Assert.DoesNotContain(typeof(IAggregator<string>), found);
    Assert.Contains(typeof(Sphere), TypeLoader.GetTypesWithInterface<ISolid>());
  }

  [Fact]
  public void GetLoadableTypes_lists_an_assembly_types()
  {
    var types = typeof(Histogram<>).Assembly.GetLoadableTypes().ToList();
    Assert.Contains(typeof(Quantiles<>), types);
    Assert.Contains(typeof(TypeLoader), types);
  }
}
