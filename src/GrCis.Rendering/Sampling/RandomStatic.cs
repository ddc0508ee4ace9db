namespace MathSupport;

/// <summary>Cheap stateless integer generators (GrCis's, with its unsigned types) and a 64-bit mix.</summary>
public class RandomStatic
{
  /// <summary>Mask of the low 32 bits.</summary>
  protected const ulong BITS_32 = 0xFFFFFFFFUL;
  /// <summary>Mask of the low 31 bits (2³¹ − 1, also Park and Miller's modulus).</summary>
  protected const ulong BITS_31 = 0x7FFFFFFFUL;

  /// <summary>One step of the Numerical Recipes linear congruential generator, kept to 32 bits.</summary>
  public static ulong numericRecipes(ulong v) => (v * 1664525UL + 1013904223UL) & BITS_32;

  /// <summary>The range of <see cref="numericRecipes"/>: its values are below 2³².</summary>
  public static ulong numericRecipesMax() => BITS_32 + 1UL;

  /// <summary>IBM's RANDU step (a famously poor generator, for teaching), 31 bits.</summary>
  public static ulong ibmRandu(ulong v) => (v * 65539UL) & BITS_31;

  /// <summary>The range of <see cref="ibmRandu"/>: its values are below 2³¹.</summary>
  public static ulong ibmRanduMax() => BITS_31 + 1UL;

  /// <summary>Park and Miller's minimal standard step.</summary>
  public static ulong parkMiller(ulong v) => (v * 16807UL) % BITS_31;

  /// <summary>The range of <see cref="parkMiller"/>: its values are below 2³¹ − 1.</summary>
  public static ulong parkMillerMax() => BITS_31;

  /// <summary>Maple's linear congruential step.</summary>
  public static ulong maple(ulong v) => (v * 427419669081UL) % 999999999989UL;

  /// <summary>The range of <see cref="maple"/>: its values are below its modulus 999999999989.</summary>
  public static ulong mapleMax() => 999999999989UL;

  /// <summary>SplitMix64 finaliser: a strong 64-bit mix used to derive independent sample streams.</summary>
  public static ulong Mix64(ulong z)
  {
    z += 0x9E3779B97F4A7C15UL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
    return z ^ (z >> 31);
  }
}
