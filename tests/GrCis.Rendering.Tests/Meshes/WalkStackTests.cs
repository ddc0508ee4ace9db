using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;
using Rendering;
using Scene3D;
using GrCis.TestSupport;
using Xunit;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>
/// The mesh walks keep their stacks in fixed buffers of their frame: a method that uses stackalloc is compiled once,
/// without a profile, and the walks' triangle test then spills its temporaries (docs/performance.md, "Against Intel
/// Embree"). The buffers must still hold the stack of every tree the builder makes for real meshes.
/// </summary>
public class WalkStackTests
{
  static readonly string[] Walks = { "Any", "Nearest", "NearestBoth", "IntersectAll" };

  static IEnumerable<MethodInfo> Bodies() =>
    typeof(MeshBvh).GetMethods(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public)
                   .Where(m => m.IsGenericMethodDefinition && Walks.Contains(m.Name));

  public static IEnumerable<object[]> WalkNames() => Walks.Select(w => new object[] { w });

  [Theory]
  [MemberData(nameof(WalkNames))]
  public void Walk_uses_no_stackalloc(string name)
  {
    MethodInfo body = Assert.Single(Bodies(), m => m.Name == name);
    Assert.DoesNotContain(OpCodes.Localloc, IlOpcodes.Of(body));
  }

  [Fact]
  public void Opcode_reader_finds_stackalloc_where_it_is()
  {
    // The reader itself: this probe allocates on the stack, so its body must show the opcode.
    MethodInfo probe = typeof(WalkStackTests).GetMethod(nameof(StackallocProbe), BindingFlags.NonPublic | BindingFlags.Static)!;
    Assert.Contains(OpCodes.Localloc, IlOpcodes.Of(probe));
  }

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

  static int StackallocProbe(int n)
  {
    Span<int> s = stackalloc int[n];
    s[0] = n;
    return s[0];
  }
}
