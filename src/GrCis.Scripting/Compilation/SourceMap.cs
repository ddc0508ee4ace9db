using System;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// The way from a line and column of the compiled (instrumented) text of a user's file back to the file as
/// written, as plain numbers: what a runtime error needs after the compilation, kept in the compiled-script
/// cache and used without the compiler. Made from an <see cref="InstrumentedSource"/>, whose mapping it repeats.
/// </summary>
internal sealed class SourceMap
{
  public SourceMap(int originalLength, int[] originalLineStarts, int instrumentedLength, int[] instrumentedLineStarts,
                   (int Position, int Length)[] insertions)
  {
    if (originalLineStarts.Length == 0 || instrumentedLineStarts.Length == 0)
      throw new ArgumentException("A text has at least one line.");
    OriginalLength = originalLength;
    OriginalLineStarts = originalLineStarts;
    InstrumentedLength = instrumentedLength;
    InstrumentedLineStarts = instrumentedLineStarts;
    Insertions = insertions;
  }

  public int OriginalLength { get; }

  /// <summary>Offset of each line of the file as written (the first is 0).</summary>
  public int[] OriginalLineStarts { get; }

  public int InstrumentedLength { get; }

  /// <summary>Offset of each line of the compiled text.</summary>
  public int[] InstrumentedLineStarts { get; }

  /// <summary>Text inserted into the original: at which original offset, how many characters (ascending).</summary>
  public (int Position, int Length)[] Insertions { get; }

  /// <summary>1-based column in the original text of a 1-based line and column of the compiled one (0 = unknown stays 0).</summary>
  public int OriginalColumn(int line, int column)
  {
    if (line <= 0 || column <= 0)
      return column;
    if (line - 1 >= InstrumentedLineStarts.Length)
      return column;
    int start = InstrumentedLineStarts[line - 1];
    int end = line < InstrumentedLineStarts.Length ? InstrumentedLineStarts[line] : InstrumentedLength;
    int offset = Math.Min(start + column - 1, end);
    int original = ToOriginal(offset);
    int at = Array.BinarySearch(OriginalLineStarts, original);
    int lineIndex = at >= 0 ? at : ~at - 1;
    return original - OriginalLineStarts[lineIndex] + 1;
  }

  /// <summary>The offset in the original text of an offset in the compiled one (inside an insertion: where it was inserted).</summary>
  public int ToOriginal(int offset) => ToOriginal(Insertions, offset, OriginalLength);

  /// <summary>The offset in the original text of <paramref name="offset"/> in a text made by <paramref name="insertions"/>.</summary>
  public static int ToOriginal((int Position, int Length)[] insertions, int offset, int originalLength)
  {
    int shift = 0;
    foreach ((int position, int length) in insertions)
    {
      int start = position + shift;
      if (offset < start)
        break;
      if (offset < start + length)
        return position;
      shift += length;
    }
    return Math.Clamp(offset - shift, 0, originalLength);
  }
}
