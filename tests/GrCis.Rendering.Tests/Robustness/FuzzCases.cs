using System;
using System.Collections.Generic;

namespace Rendering.Tests.Robustness;

/// <summary>Seeded damage to a valid file: every (or many) truncations, bit flips, overwritten bursts, random tails and random bytes.</summary>
internal static class FuzzCases
{
  public static IEnumerable<(string Name, byte[] Bytes)> Of(string name, byte[] valid, int seed, int flips = 300, int bursts = 150, int tails = 80, int randoms = 40)
  {
    var rng = new Random(seed);
    int step = Math.Max(1, valid.Length / 1200);
    for (int n = 0; n < valid.Length; n += step)
      yield return ($"{name} truncated to {n} bytes", valid[..n]);

    for (int k = 0; k < flips; k++)
    {
      byte[] b = (byte[])valid.Clone();
      int at = rng.Next(b.Length), bit = rng.Next(8);
      b[at] ^= (byte)(1 << bit);
      yield return ($"{name} with bit {bit} of byte {at} flipped", b);
    }

    for (int k = 0; k < bursts; k++)
    {
      byte[] b = (byte[])valid.Clone();
      int at = rng.Next(b.Length), len = rng.Next(1, 9);
      for (int i = at; i < Math.Min(b.Length, at + len); i++)
        b[i] = (byte)rng.Next(256);
      yield return ($"{name} with bytes {at}..{at + len - 1} overwritten (seed {seed}, burst {k})", b);
    }

    for (int k = 0; k < tails; k++)
    {
      int keep = rng.Next(Math.Min(valid.Length, 64) + 1);
      byte[] b = new byte[keep + rng.Next(2 * valid.Length)];
      valid.AsSpan(0, keep).CopyTo(b);
      rng.NextBytes(b.AsSpan(keep));
      yield return ($"{name}'s first {keep} bytes then random (seed {seed}, tail {k})", b);
    }

    for (int k = 0; k < randoms; k++)
    {
      byte[] b = new byte[rng.Next(1, 2 * valid.Length)];
      rng.NextBytes(b);
      yield return ($"random bytes (seed {seed}, case {k} of {name})", b);
    }
  }
}
