using System;
using System.Reflection;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;
using Xunit;

namespace GrCis.Rendering.Tests.Execution;

/// <summary>
/// The hot methods a render's first moments compile twice when they are inlined: tier-0 callers call them, so they
/// are promoted to tier 1 on their own and again inside every caller (docs/performance.md, "Start-up"). They stay
/// calls, so the JIT compiles each body once.
/// </summary>
public class JitBoundaryTests
{
  [Theory]
  [InlineData(typeof(SupersamplingImageSynthesizer), nameof(SupersamplingImageSynthesizer.AccumulateSamples))]
  [InlineData(typeof(PreparedScene), nameof(PreparedScene.Occluded))]
  public void Sample_loop_and_shadow_query_are_never_inlined(Type type, string name)
  {
    MethodInfo method = Assert.Single(type.GetMethods(BindingFlags.Public | BindingFlags.Instance), m => m.Name == name);
    Assert.True((method.MethodImplementationFlags & MethodImplAttributes.NoInlining) != 0,
                $"{type.Name}.{name} lost [MethodImpl(MethodImplOptions.NoInlining)]");
  }

  [Fact]
  public void Ball_cull_is_optimized_at_its_first_call()
  {
    // Its 256-bit vectors keep it out of the ReadyToRun image: without the attribute a render's first rays run it as
    // tier-0 code (docs/performance.md, "A render's first moments").
    MethodInfo method = Assert.Single(typeof(PreparedScene).GetMethods(BindingFlags.NonPublic | BindingFlags.Instance), m => m.Name == "Balls");
    Assert.True((method.MethodImplementationFlags & MethodImplAttributes.AggressiveOptimization) != 0,
                "PreparedScene.Balls lost [MethodImpl(MethodImplOptions.AggressiveOptimization)]");
  }

  [Theory]
  [InlineData(nameof(PngFilter.Apply))]
  [InlineData(nameof(PngFilter.Cost))]
  public void Png_filters_are_optimized_at_their_first_call(string name)
  {
    // Their 128-bit vectors keep them out of the ReadyToRun image: a fresh process's save would filter every row five
    // times in tier-0 code.
    MethodInfo method = Assert.Single(typeof(PngFilter).GetMethods(BindingFlags.Public | BindingFlags.Static), m => m.Name == name);
    Assert.True((method.MethodImplementationFlags & MethodImplAttributes.AggressiveOptimization) != 0,
                $"PngFilter.{name} lost [MethodImpl(MethodImplOptions.AggressiveOptimization)]");
  }

  [Fact]
  public void Shadow_query_through_AnyHit_sees_the_ball_between_origin_and_light()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(new Sphere(), Matrix4d.Identity);
    root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
    PreparedScene prepared = PreparedScene.Prepare(root);
    var p0 = new Vector3d(-3.0, 0.0, 0.0);
    foreach (Vector3d dir in new[] { new Vector3d(6.0, 0.0, 0.0), new Vector3d(1.0, 0.0, 0.0), new Vector3d(0.0, 5.0, 0.0) })
      Assert.Equal(prepared.Occluded(p0, dir), prepared.AnyHit(p0, dir));
    Assert.True(prepared.AnyHit(p0, new Vector3d(6.0, 0.0, 0.0)));
    Assert.False(prepared.AnyHit(p0, new Vector3d(1.0, 0.0, 0.0)));
  }
}
