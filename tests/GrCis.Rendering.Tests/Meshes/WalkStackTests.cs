using System;
using System.IO;
using System.Reflection;
using Rendering;
using Scene3D;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The mesh walks keep their stacks in fixed buffers of their frame (no stackalloc: FixedFrameTests, docs/performance.md,
/// "Against Intel Embree"); the buffers must hold the stack of every tree the builder makes for real meshes.
/// </summary>
public class WalkStackTests
{
  [Theory]
  [InlineData("teapot.obj.gz")]
  [InlineData("pitcher.obj.gz")]
  [InlineData("toyplane.obj.gz")]
  [InlineData("buddha.obj.gz")]
  public void Frame_buffers_hold_the_stack_of_real_meshes(string file)
  {
    var scene = new SceneBrep();
    new WavefrontObj().ReadBrep(Path.Combine(MeshTestSupport.MeshDir, file), scene);
    var bvh = new MeshBvh(scene);
    int stackSize = (int)typeof(MeshBvh).GetField("stackSize", BindingFlags.Instance | BindingFlags.NonPublic)!.GetValue(bvh)!;
    Assert.InRange(stackSize, 2, Math.Min(MeshBvh.FrameEntries, MeshBvh.FrameSpanEntries));
  }
}
