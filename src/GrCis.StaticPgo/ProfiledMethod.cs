using System.Collections.Generic;
using System.Linq;

namespace GrCis.StaticPgo;

/// <summary>A method's counts from one or more training runs, named as the runtime names it in its text dump.</summary>
internal sealed class ProfiledMethod
{
  /// <summary>Type and method, "Rendering.Accel.PreparedScene.FirstHit" (nested types with '+').</summary>
  public required string Name { get; init; }

  /// <summary>The runtime's spelling of the signature, "instance bool  (float64,float64)".</summary>
  public required string Signature { get; init; }

  public required int IlSize { get; init; }
  public required List<SchemaEntry> Schema { get; init; }

  public string Key => Name + "|" + Signature + "|" + IlSize;

  /// <summary>The number of parameters the signature lists (commas at the outer level of its parentheses).</summary>
  public int ParameterCount
  {
    get
    {
      int open = Signature.LastIndexOf('('), close = Signature.LastIndexOf(')');
      if (open < 0 || close <= open + 1) return 0;
      int depth = 0, count = 1;
      for (int i = open + 1; i < close; i++)
        switch (Signature[i])
        {
          case '<' or '[': depth++; break;
          case '>' or ']': depth--; break;
          case ',' when depth == 0: count++; break;
        }
      return count;
    }
  }

  /// <summary>
  /// Adds another run's counts of the same method: block and edge counts add up; a histogram (its count and its
  /// slots) is the one of the run that saw more calls. A run whose schema differs (another compilation plan) is left
  /// out rather than mixed in.
  /// </summary>
  public void Add(ProfiledMethod other)
  {
    if (other.Schema.Count != Schema.Count) return;
    for (int i = 0; i < Schema.Count; i++)
      if (!Schema[i].SameSlotAs(other.Schema[i])) return;
    for (int i = 0; i < Schema.Count; i++)
    {
      SchemaEntry mine = Schema[i], theirs = other.Schema[i];
      if (mine.IsCount)
        for (int v = 0; v < mine.Values.Length; v++) mine.Values[v] += theirs.Values[v];
      else if (mine.IsHistogramCount && i + 1 < Schema.Count && Schema[i + 1].IlOffset == mine.IlOffset && theirs.Values.Sum() > mine.Values.Sum())
      {
        Schema[i] = theirs;
        Schema[i + 1] = other.Schema[i + 1];
        i++;
      }
    }
  }
}
