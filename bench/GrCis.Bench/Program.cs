using System;
using BenchmarkDotNet.Running;

namespace GrCis.Bench;

/// <summary>
/// <c>dotnet run -c Release -- quick [...]</c>: Stopwatch scene timings (fast vs faithful path);
/// <c>pngsize FILE…</c>: PNG sizes of both encoders;
/// <c>soak [--renders N] [--csv FILE]</c>: memory over many edit-and-render cycles in one process;
/// <c>plots [--out DIR] …</c>: the figures of bench/results as PNG (see <see cref="Plots.PlotsCommand"/>);
/// <c>embree [--mesh FILE] …</c>: the library's ray queries against Intel Embree's on the same rays (see <see cref="Embree.EmbreeComparison"/>);
/// <c>studio SCRIPTS_DIR</c>: the studio's latencies; <c>editor SCRIPTS_DIR</c>: the editor services' latencies;
/// anything else goes to BenchmarkDotNet (e.g. <c>--filter *Kernel*</c>).
/// </summary>
public static class Program
{
  public static int Main(string[] args)
  {
    if (args.Length > 0 && args[0] == "probe")
      return Probe.Run();
    if (args.Length > 0 && args[0] == "pngsize")
      return PngSizes.Run(args[1..]);
    if (args.Length > 0 && args[0] == "soak")
      return Soak.Run(args[1..]);
    if (args.Length > 0 && args[0] == "studio")
      return StudioMeasure.Run(args[1..]);
    if (args.Length > 0 && args[0] == "editor")
      return EditorMeasure.Run(args[1..]);
    if (args.Length > 0 && args[0] == "plots")
      return Plots.PlotsCommand.Run(args[1..]);
    if (args.Length > 0 && args[0] == "embree")
      return Embree.EmbreeComparison.Run(args[1..], Console.Out, Console.Error);
    if (args.Length > 0 && args[0] == "quick")
      return QuickRun.Run(args[1..]);
    BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
    return 0;
  }
}
