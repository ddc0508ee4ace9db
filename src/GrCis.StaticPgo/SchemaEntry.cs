namespace GrCis.StaticPgo;

/// <summary>
/// One record of a method's instrumentation schema, as the runtime lists it: what was counted (the kind), where in the
/// IL, how many values, the kind's extra number (an edge's target offset, a histogram's flags) and the values.
/// </summary>
/// <remarks>
/// The kind's low four bits say how a value is stored (<see cref="Marshal"/>); the bits from 6 up say what it is
/// (<see cref="Descriptor"/>), the numbering of the runtime's <c>PgoInstrumentationKind</c>.
/// </remarks>
internal sealed class SchemaEntry
{
  public const int None = 0, FourByte = 1, EightByte = 2, TypeHandle = 3, MethodHandle = 4;
  public const int BlockCount = 1, HistogramCount = 2, Histogram = 3, EdgeCount = 6, ValueHistogramCount = 8;

  public required int Kind { get; init; }
  public required int IlOffset { get; init; }
  public required int Count { get; init; }
  public required int Other { get; init; }

  /// <summary>The counts (four- or eight-byte kinds); zeros for handles.</summary>
  public required long[] Values { get; init; }

  /// <summary>The names of the type or method handles (handle kinds), "NULL" or "UNKNOWN" as the runtime wrote them.</summary>
  public required string[] Handles { get; init; }

  public int Marshal => Kind & 0xF;
  public int Descriptor => Kind >> 6;

  /// <summary>A block or edge count: counts that add up across runs.</summary>
  public bool IsCount => Descriptor is BlockCount or EdgeCount;

  /// <summary>The call count of a histogram (the records after it are its slots).</summary>
  public bool IsHistogramCount => Descriptor is HistogramCount or ValueHistogramCount;

  public bool SameSlotAs(SchemaEntry other) =>
    Kind == other.Kind && IlOffset == other.IlOffset && Count == other.Count && Other == other.Other;
}
