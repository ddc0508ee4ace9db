using System;
using System.Collections;
using System.Collections.Generic;
using System.Text;

namespace Utilities;

/// <summary>
/// GrCis's bit-array helpers, including a compact text form: hex digits, four bits each, the first bit as
/// the digit's highest; "(n)" stands for n zero digits and "{n}" for n "F" digits; trailing zeros are left out.
/// </summary>
public static partial class Util
{
  /// <summary>Sets bit <paramref name="i"/>, growing the array to a multiple of <paramref name="granularity"/> when needed.</summary>
  public static void BitArraySet(BitArray ba, int i, int granularity = 32)
  {
    if (i >= ba.Count)
      ba.Length = granularity < 2 ? i + 1 : (i / granularity + 1) * granularity;
    ba[i] = true;
  }

  /// <summary>
  /// Drops whole trailing blocks of <paramref name="granularity"/> zero bits, keeping at least one block; arrays
  /// shorter than two blocks are left alone. Returns the same array.
  /// </summary>
  public static BitArray? BitArrayTrim(BitArray? ba, int granularity = 32)
  {
    // A block of no bits would never end: one bit is the finest there is.
    granularity = Math.Max(granularity, 1);
    if (ba == null || ba.Count < 2 * granularity)
      return ba;
    int last = ba.Count - 1;
    while (last >= granularity && !ba[last])
      last--;
    ba.Length = (last / granularity + 1) * granularity;
    return ba;
  }

  /// <summary>The compact text form of <paramref name="ba"/> (trimmed first when <paramref name="granularity"/> &gt; 0); "" for null or empty.</summary>
  public static string BitArrayToString(BitArray? ba, int granularity = 0)
  {
    if (ba == null)
      return "";
    if (granularity > 0)
      BitArrayTrim(ba, granularity);

    var sb = new StringBuilder();
    char runDigit = '0';
    int runLength = 0;
    int digits = (ba.Count + 3) / 4;
    for (int d = 0; d < digits; d++)
    {
      int nibble = 0;
      for (int b = 0; b < 4; b++)
      {
        int bit = 4 * d + b;
        if (bit < ba.Count && ba[bit])
          nibble |= 8 >> b;
      }
      char digit = "0123456789ABCDEF"[nibble];
      if (runLength > 0 && digit == runDigit)
      {
        runLength++;
        continue;
      }
      AppendRun(sb, runDigit, runLength);
      runLength = 0;
      if (digit is '0' or 'F')
      {
        runDigit = digit;
        runLength = 1;
      }
      else
        sb.Append(digit);
    }
    // Trailing zeros carry no information.
    if (runDigit != '0')
      AppendRun(sb, runDigit, runLength);
    return sb.ToString();
  }

  static void AppendRun(StringBuilder sb, char digit, int length)
  {
    if (length > 3)
      sb.Append(digit == '0' ? '(' : '{').Append(length).Append(digit == '0' ? ')' : '}');
    else
      sb.Append(digit, length);
  }

  /// <summary>Value of a hex digit; 0 for any other character.</summary>
  public static int HexDigit(char d) =>
    d >= '0' && d <= '9' ? d - '0'
    : d >= 'a' && d <= 'f' ? 10 + d - 'a'
    : d >= 'A' && d <= 'F' ? 10 + d - 'A'
    : 0;

  /// <summary>Reads the compact text form back (null for null or ""), sized in blocks of <paramref name="granularity"/> bits and trimmed.</summary>
  public static BitArray? StringToBitArray(string? s, int granularity = 32)
  {
    if (string.IsNullOrEmpty(s))
      return null;
    granularity = Math.Max(granularity, 1);
    var ba = new BitArray(granularity);
    int bit = 0;

    void Put(int nibble)
    {
      if (bit + 4 > ba.Count)
        ba.Length = ((bit + 4) / granularity + 1) * granularity;
      for (int b = 0; b < 4; b++)
        ba[bit + b] = (nibble & (8 >> b)) != 0;
      bit += 4;
    }

    for (int i = 0; i < s.Length; i++)
    {
      if (s[i] is '(' or '{')
      {
        int nibble = s[i] == '{' ? 15 : 0;
        int end = i + 1;
        while (end < s.Length && char.IsAsciiDigit(s[end]))
          end++;
        int count = int.TryParse(s.AsSpan(i + 1, end - i - 1), out int n) ? n : 0;
        while (count-- > 0)
          Put(nibble);
        i = end;   // skips the closing bracket
        continue;
      }
      Put(HexDigit(s[i]));
    }
    return BitArrayTrim(ba, granularity);
  }

  /// <summary>
  /// Rebuilds <paramref name="proc"/> unless it already has one entry per bit: entry i is 0 where bit i is set,
  /// else the number of clear bits since the last set one (counting bit i).
  /// </summary>
  public static void CheckRebuildCachedList(BitArray? ba, ref List<ushort>? proc)
  {
    if (ba == null || (proc != null && proc.Count == ba.Count))
      return;
    proc = new List<ushort>(ba.Count);
    ushort since = 0;
    for (int i = 0; i < ba.Count; i++)
    {
      since = ba[i] ? (ushort)0 : (ushort)(since + 1);
      proc.Add(since);
    }
  }

  /// <summary>Little-endian integer of <paramref name="len"/> bytes at <paramref name="i"/>; 0 when the range is not inside <paramref name="data"/>.</summary>
  public static long DecodeNumber(byte[]? data, int i, int len)
  {
    if (data == null || i < 0 || len < 1 || data.Length < i + len)
      return 0L;
    long result = 0L;
    for (int b = len - 1; b >= 0; b--)
      result = (result << 8) | data[i + b];
    return result;
  }

  public static uint DecodeUnsigned(byte[]? data, int i) => (uint)DecodeNumber(data, i, 4);

  public static long DecodeLong(byte[]? data, int i) => DecodeNumber(data, i, 8);

  public static short DecodeShort(byte[]? data, int i) => (short)DecodeNumber(data, i, 2);

  /// <summary>
  /// Joins the two cyclic lists (arr[k] = next member after k) that hold <paramref name="start1"/> and
  /// <paramref name="start2"/>; they must be different lists (the same list would be split instead).
  /// </summary>
  public static void MergeCyclicLists(int[] arr, int start1, int start2) =>
    (arr[start1], arr[start2]) = (arr[start2], arr[start1]);

  /// <summary>n one-member cyclic lists for <see cref="MergeCyclicLists"/>: arr[i] = i.</summary>
  public static int[] CyclicArray(int n)
  {
    int[] arr = new int[n];
    for (int i = 0; i < n; i++)
      arr[i] = i;
    return arr;
  }
}
