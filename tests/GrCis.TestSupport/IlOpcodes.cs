using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Reflection.Emit;

namespace GrCis.TestSupport;

/// <summary>
/// The opcodes of a method's IL body in order, each operand skipped by its encoded size: for tests that hold a method
/// to a shape the JIT compiles well (no <c>stackalloc</c>, <see cref="OpCodes.Localloc"/>, in a per-ray method).
/// </summary>
public static class IlOpcodes
{
  static readonly Dictionary<short, OpCode> byValue = typeof(OpCodes).GetFields(BindingFlags.Public | BindingFlags.Static)
    .Select(f => (OpCode)f.GetValue(null)!).ToDictionary(o => o.Value);

  /// <summary>The opcodes of <paramref name="method"/>'s body (empty for a method without one).</summary>
  public static List<OpCode> Of(MethodBase method)
  {
    byte[] il = method.GetMethodBody()?.GetILAsByteArray() ?? [];
    var ops = new List<OpCode>();
    for (int i = 0; i < il.Length;)
    {
      OpCode op = byValue[il[i] == 0xFE ? (short)(0xFE00 | il[i + 1]) : il[i]];
      i += op.Size;
      ops.Add(op);
      i += op.OperandType switch
      {
        OperandType.InlineNone => 0,
        OperandType.ShortInlineBrTarget or OperandType.ShortInlineI or OperandType.ShortInlineVar => 1,
        OperandType.InlineVar => 2,
        OperandType.InlineI8 or OperandType.InlineR => 8,
        OperandType.InlineSwitch => 4 + 4 * BitConverter.ToInt32(il, i),
        _ => 4,
      };
    }
    return ops;
  }

  /// <summary>Whether <paramref name="method"/> allocates on the stack (<c>stackalloc</c>).</summary>
  public static bool UsesLocalloc(MethodBase method) => Of(method).Contains(OpCodes.Localloc);
}
