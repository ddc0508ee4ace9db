using System.Collections;
using System.Collections.Generic;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>GrCis's bit arrays and their compact text, byte decoding, cyclic lists.</summary>
public class UtilBitsTests
{
  static BitArray Bits(int count, params int[] set)
  {
    var ba = new BitArray(count);
    foreach (int i in set)
      ba[i] = true;
    return ba;
  }

  [Theory]
  [InlineData(new[] { 0 }, "8")]
  [InlineData(new[] { 3, 4 }, "18")]
  [InlineData(new[] { 0, 1, 2, 3 }, "F")]
  [InlineData(new[] { 20 }, "(5)8")]
  [InlineData(new[] { 12 }, "0008")]
  public void BitArrayToString_writes_hex_digits_with_runs_and_no_trailing_zeros(int[] set, string expected) =>
    Assert.Equal(expected, Util.BitArrayToString(Bits(64, set)));

  [Fact]
  public void A_run_of_ones_is_braced()
  {
    var ones = new int[24];
    for (int i = 0; i < 24; i++)
      ones[i] = i;
    Assert.Equal("{6}", Util.BitArrayToString(Bits(32, ones)));
    Assert.Equal("FFF", Util.BitArrayToString(Bits(32, ones[..12])));
  }

  [Theory]
  [InlineData("8")]
  [InlineData("(5)8")]
  [InlineData("A{4}3(7)1")]
  [InlineData("{9}")]
  public void StringToBitArray_reads_back_what_BitArrayToString_wrote(string text)
  {
    BitArray ba = Util.StringToBitArray(text)!;
    Assert.Equal(0, ba.Count % 32);
    Assert.Equal(text, Util.BitArrayToString(ba));
  }

  [Fact]
  public void StringToBitArray_sets_the_named_bits_and_trims_to_whole_blocks()
  {
    BitArray ba = Util.StringToBitArray("(16)1", 32)!;
    Assert.Equal(96, ba.Count);
    Assert.True(ba[67]);
    Assert.False(ba[66] || ba[64]);
    Assert.Null(Util.StringToBitArray(""));
  }

  [Fact]
  public void BitArrayTrim_and_Set_work_in_blocks()
  {
    BitArray ba = Bits(128, 5);
    Assert.Equal(32, Util.BitArrayTrim(ba)!.Count);
    Util.BitArraySet(ba, 40);
    Assert.Equal(64, ba.Count);
    Assert.True(ba[40] && ba[5]);
    Util.BitArraySet(ba, 70, 1);
    Assert.Equal(71, ba.Count);
    Assert.Equal(40, Util.BitArrayTrim(Bits(40, 1), 32)!.Count);   // shorter than two blocks: left alone
  }

  [Fact]
  public void CheckRebuildCachedList_counts_clear_bits_since_the_last_set_one()
  {
    List<ushort>? cache = null;
    Util.CheckRebuildCachedList(Bits(6, 2, 3), ref cache);
    Assert.Equal(new ushort[] { 1, 2, 0, 0, 1, 2 }, cache);
    List<ushort> kept = cache!;
    Util.CheckRebuildCachedList(Bits(6, 0), ref cache);
    Assert.Same(kept, cache);   // same length: the cache is trusted
  }

  [Theory]
  [InlineData(new byte[] { 0x34, 0x12 }, 0, 2, 0x1234L)]
  [InlineData(new byte[] { 9, 0x78, 0x56, 0x34, 0x12 }, 1, 4, 0x12345678L)]
  [InlineData(new byte[] { 1, 2 }, 1, 2, 0L)]
  [InlineData(new byte[] { 1, 2 }, -1, 1, 0L)]
  public void DecodeNumber_is_little_endian_and_zero_out_of_range(byte[] data, int i, int len, long expected) =>
    Assert.Equal(expected, Util.DecodeNumber(data, i, len));

  [Fact]
  public void Typed_decoders_reinterpret_the_bytes()
  {
    byte[] data = { 0xFE, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x7F };
    Assert.Equal((short)-2, Util.DecodeShort(data, 0));
    Assert.Equal(0xFFFFFFFEu, Util.DecodeUnsigned(data, 0));
    Assert.Equal(long.MaxValue - 1, Util.DecodeLong(data, 0));
  }

  [Fact]
  public void Merged_cyclic_lists_cycle_through_both_groups()
  {
    int[] next = Util.CyclicArray(5);
    Assert.Equal(new[] { 0, 1, 2, 3, 4 }, next);
    Util.MergeCyclicLists(next, 0, 1);
    Util.MergeCyclicLists(next, 1, 3);
    var cycle = new SortedSet<int> { 0 };
    for (int i = next[0]; i != 0; i = next[i])
      Assert.True(cycle.Add(i));
    Assert.Equal(new[] { 0, 1, 3 }, cycle);
    Assert.Equal(2, next[2]);
  }
}
