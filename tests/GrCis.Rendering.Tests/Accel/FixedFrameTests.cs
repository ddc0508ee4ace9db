using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using GrCis.TestSupport;
using Rendering;
using Rendering.Accel;
using Xunit;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The per-ray methods of the fast path and the mesh walks keep fixed frames: no <c>stackalloc</c> (IL <c>localloc</c>).
/// The JIT turns only allocations of up to 32 bytes into plain locals; a larger one gives its method a variable frame
/// and a stack-guard check on every return, which made the JIT-compiled build render the small scenes 3–5 % slower
/// (bench/results/2026-12-07-fixed-frames.md), and a method with a loop and a stack allocation is compiled once,
/// without a profile (the mesh walks' triangle test then spilled its temporaries). Buffers are fixed-size inline
/// arrays (<see cref="WalkStack{T}"/>, the kernel's band buffers, <see cref="MeshBvh"/>'s frame buffers) instead.
/// </summary>
public class FixedFrameTests
{
  /// <summary>Every method of the types a ray passes through, and the sample loop that calls them.</summary>
  static IEnumerable<MethodBase> PerRay()
  {
    const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
    foreach (Type t in new[] { typeof(WhittedKernel), typeof(PreparedScene), typeof(PhongModel) })
      foreach (MethodInfo m in t.GetMethods(all))
        if (m.GetMethodBody() != null)
          yield return m;
    yield return typeof(SupersamplingImageSynthesizer).GetMethod(nameof(SupersamplingImageSynthesizer.AccumulateSamples))!;
    // The mesh walks (generic: their definitions' IL).
    string[] walks = { "Any", "Nearest", "NearestBoth", "IntersectAll" };
    MethodInfo[] meshWalks = typeof(MeshBvh).GetMethods(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public)
      .Where(m => m.IsGenericMethodDefinition && walks.Contains(m.Name)).ToArray();
    Assert.Equal(walks.Length, meshWalks.Length);
    foreach (MethodInfo m in meshWalks)
      yield return m;
  }

  static string Name(MethodBase m) =>
    $"{m.DeclaringType!.Name}.{m.Name}({string.Join(", ", m.GetParameters().Select(p => p.ParameterType.Name))})";

  [Fact]
  public void Per_ray_methods_have_no_stack_allocation()
  {
    MethodBase[] methods = PerRay().ToArray();
    Assert.True(methods.Length > 40, $"only {methods.Length} per-ray methods found");
    string[] offenders = methods.Where(IlOpcodes.UsesLocalloc).Select(Name).ToArray();
    Assert.True(offenders.Length == 0,
      $"stackalloc (IL localloc) in {string.Join("; ", offenders)}: use a fixed-size inline array instead.");
  }

  [Fact]
  public void Opcode_reader_finds_stackalloc_where_it_is()
  {
    // The reader itself: this probe allocates on the stack, so its body must show the opcode.
    MethodInfo probe = typeof(FixedFrameTests).GetMethod(nameof(StackallocProbe), BindingFlags.NonPublic | BindingFlags.Static)!;
    Assert.True(IlOpcodes.UsesLocalloc(probe));
    Assert.False(IlOpcodes.UsesLocalloc(typeof(FixedFrameTests).GetMethod(nameof(Name), BindingFlags.NonPublic | BindingFlags.Static)!));
  }

  static int StackallocProbe(int n)
  {
    Span<int> s = stackalloc int[n];
    s[0] = n;
    return s[0];
  }
}
