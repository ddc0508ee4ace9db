using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The per-ray methods of the fast path keep fixed frames: no <c>stackalloc</c> (IL <c>localloc</c>). The JIT turns
/// only allocations of up to 32 bytes into plain locals; a larger one gives its method a variable frame and a
/// stack-guard check on every return, which made the JIT-compiled build render the small scenes 3–5 % slower
/// (bench/results/2026-12-07-fixed-frames.md). Buffers are fixed-size inline arrays (<see cref="WalkStack{T}"/>,
/// the kernel's band buffers) instead.
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
  }

  static string Name(MethodBase m) =>
    $"{m.DeclaringType!.Name}.{m.Name}({string.Join(", ", m.GetParameters().Select(p => p.ParameterType.Name))})";

  [Fact]
  public void Per_ray_methods_have_no_stack_allocation()
  {
    string[] offenders = PerRay().Where(UsesLocalloc).Select(Name).ToArray();
    Assert.True(offenders.Length == 0,
      $"stackalloc (IL localloc) in {string.Join("; ", offenders)}: use a fixed-size inline array instead.");
  }

  [Fact]
  public void The_scan_finds_a_stack_allocation()
  {
    // The scan itself: a method with a large stackalloc must be reported, one without must not.
    Assert.True(UsesLocalloc(typeof(FixedFrameTests).GetMethod(nameof(WithStackalloc), BindingFlags.NonPublic | BindingFlags.Static)!));
    Assert.False(UsesLocalloc(typeof(FixedFrameTests).GetMethod(nameof(WithoutStackalloc), BindingFlags.NonPublic | BindingFlags.Static)!));
    Assert.True(PerRay().Count() > 40, "the per-ray types were found");
  }

  static double WithStackalloc(int n)
  {
    Span<double> s = stackalloc double[16];
    s[n & 15] = n;
    return s[0];
  }

  static double WithoutStackalloc(int n)
  {
    var s = new double[16];
    s[n & 15] = n;
    return s[0];
  }

  static readonly Dictionary<short, OpCode> opCodes = typeof(OpCodes).GetFields(BindingFlags.Public | BindingFlags.Static)
    .Select(f => (OpCode)f.GetValue(null)!).ToDictionary(o => o.Value);

  /// <summary>Walks the method's IL instruction by instruction (operands skipped by their sizes) looking for localloc.</summary>
  static bool UsesLocalloc(MethodBase method)
  {
    byte[] il = method.GetMethodBody()!.GetILAsByteArray()!;
    int k = 0;
    while (k < il.Length)
    {
      short value = il[k] == 0xFE ? (short)(0xFE00 | il[k + 1]) : il[k];
      k += il[k] == 0xFE ? 2 : 1;
      OpCode op = opCodes[value];
      if (op == OpCodes.Localloc)
        return true;
      k += op.OperandType switch
      {
        OperandType.InlineNone => 0,
        OperandType.ShortInlineBrTarget or OperandType.ShortInlineI or OperandType.ShortInlineVar => 1,
        OperandType.InlineVar => 2,
        OperandType.InlineI8 or OperandType.InlineR => 8,
        OperandType.InlineSwitch => 4 + 4 * BitConverter.ToInt32(il, k),
        _ => 4,
      };
    }
    return false;
  }
}
