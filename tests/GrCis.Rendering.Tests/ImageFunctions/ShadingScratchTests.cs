using Rendering;

namespace GrCis.Rendering.Tests.ImageFunctions;

/// <summary>The per-depth pools of a thread's <see cref="ShadingScratch"/>: one object per depth, grown on demand.</summary>
public class ShadingScratchTests
{
  [Fact]
  public void Each_depth_keeps_its_own_objects_below_and_beyond_the_first_pool_size()
  {
    var scratch = new ShadingScratch();
    Intersection first = scratch.Intersection(0);
    Intersection deep = scratch.Intersection(40);
    Assert.NotSame(first, deep);
    // Growing the pool for a deeper level keeps the objects the shallower levels hold.
    Intersection deeper = scratch.Intersection(100);
    Assert.Same(first, scratch.Intersection(0));
    Assert.Same(deep, scratch.Intersection(40));
    Assert.Same(deeper, scratch.Intersection(100));

    double[] buffer = scratch.Buffer(3, 3);
    buffer[1] = 7.0;
    double[] grown = scratch.Buffer(50, 3);
    Assert.NotSame(buffer, grown);
    // The same depth's buffer again, cleared.
    Assert.Same(buffer, scratch.Buffer(3, 3));
    Assert.Equal(new[] { 0.0, 0.0, 0.0 }, buffer);
    Assert.Equal(4, scratch.Buffer(60, 4).Length);

    var material = new PhongMaterial(new[] { 0.2, 0.3, 0.4 }, 0.1, 0.6, 0.3, 16);
    var surface = new[] { 1.0, 0.5, 0.25 };
    IMaterial copy = scratch.Material(material, surface, 30);
    Assert.NotSame(material, copy);
    Assert.Same(copy, scratch.Material(material, surface, 30));
    Assert.Same(surface, copy.Color);
  }
}
