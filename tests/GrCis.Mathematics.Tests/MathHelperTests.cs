using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

public class MathHelperTests
{
  [Fact]
  public void Pi_constants_are_single_precision_like_OpenTK()
  {
    // GrCis scenes rotate the floor by -MathHelper.PiOver2; the reference images depend on this exact value.
    double piOver2 = MathHelper.PiOver2;
    Assert.Equal(1.5707963705062866, piOver2);
    Assert.Equal((double)(float)System.Math.PI, (double)MathHelper.Pi);
    Assert.NotEqual(System.Math.PI / 2.0, piOver2);
  }
}
