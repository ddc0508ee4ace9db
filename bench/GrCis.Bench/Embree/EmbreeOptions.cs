using System;
using System.Globalization;
using System.Linq;

namespace GrCis.Bench.Embree;

/// <summary>Settings of <see cref="EmbreeComparison"/>.</summary>
public sealed class EmbreeOptions
{
  /// <summary>An OBJ file (.obj or .obj.gz); null: a procedural torus of 100,000 triangles.</summary>
  public string? MeshFile { get; set; }

  /// <summary>Camera rays per side (size² rays).</summary>
  public int Size { get; set; } = 512;

  /// <summary>Incoherent rays and segments.</summary>
  public int Rays { get; set; } = 200_000;

  public int[] Threads { get; set; } = { 1, 2 };

  /// <summary>Rounds; the median is reported.</summary>
  public int Repeats { get; set; } = 3;

  public int Seed { get; set; } = 1;

  /// <summary>
  /// False (default, <c>--order interleaved</c>): each round times every query in turn, so a load that comes and goes
  /// hits them alike. True (<c>--order grouped</c>): each query's rounds back to back, so no other query's data passes
  /// through the caches between its rounds.
  /// </summary>
  public bool Grouped { get; set; }

  /// <summary>Also write the report as a table here (<c>--tsv FILE</c>, see <see cref="EmbreeTsv"/>); null: none.</summary>
  public string? TsvFile { get; set; }

  /// <summary>
  /// False (default, <c>--clock wall</c>): elapsed time. True (<c>--clock cpu</c>, one thread only): the timing thread's
  /// own processor time, so time slices lost to other processes on a shared machine are not counted (their effect on
  /// the caches still is).
  /// </summary>
  public bool ThreadCpu { get; set; }

  public static EmbreeOptions Parse(string[] args)
  {
    var o = new EmbreeOptions();
    for (int i = 0; i < args.Length; i++)
    {
      string value = i + 1 < args.Length ? args[i + 1] : throw new ArgumentException($"{args[i]} needs a value");
      switch (args[i])
      {
        case "--mesh": o.MeshFile = value; break;
        case "--size": o.Size = Positive(args[i], value); break;
        case "--rays": o.Rays = Positive(args[i], value); break;
        case "--threads": o.Threads = value.Split(',').Select(v => Positive(args[i], v)).ToArray(); break;
        case "--repeats": o.Repeats = Positive(args[i], value); break;
        case "--seed": o.Seed = int.Parse(value, CultureInfo.InvariantCulture); break;
        case "--tsv": o.TsvFile = value; break;
        case "--order":
          o.Grouped = value switch
          {
            "interleaved" => false,
            "grouped" => true,
            _ => throw new ArgumentException($"--order: '{value}' is not interleaved or grouped"),
          };
          break;
        case "--clock":
          o.ThreadCpu = value switch
          {
            "wall" => false,
            "cpu" => true,
            _ => throw new ArgumentException($"--clock: '{value}' is not wall or cpu"),
          };
          break;
        default: throw new ArgumentException($"unknown option '{args[i]}' (--mesh, --size, --rays, --threads, --repeats, --seed, --order, --clock, --tsv)");
      }
      i++;
    }
    if (o.ThreadCpu && o.Threads.Any(t => t != 1))
      throw new ArgumentException("--clock cpu measures one thread: use it with --threads 1");
    return o;
  }

  static int Positive(string option, string value) =>
    int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n > 0 ? n : throw new ArgumentException($"{option}: '{value}' is not a positive whole number");
}
