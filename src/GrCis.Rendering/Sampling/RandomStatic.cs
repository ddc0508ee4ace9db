namespace MathSupport;

/// <summary>Cheap stateless integer hashes.</summary>
public static class RandomStatic
{
  /// <summary>One step of the Numerical Recipes linear congruential generator, kept to 32 bits.</summary>
  public static ulong numericRecipes(ulong v) => (v * 1664525UL + 1013904223UL) & 0xFFFFFFFFUL;

  public static long numericRecipes(long v) => (long)numericRecipes((ulong)v);

  public static ulong numericRecipesMax() => 0x100000000UL;

  /// <summary>SplitMix64 finaliser: a strong 64-bit mix used to derive independent sample streams.</summary>
  public static ulong Mix64(ulong z)
  {
    z += 0x9E3779B97F4A7C15UL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
    return z ^ (z >> 31);
  }
}
