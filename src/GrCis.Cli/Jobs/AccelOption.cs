using System.CommandLine;
using Rendering.Accel;

namespace GrCis.Cli.Jobs;

/// <summary>The <c>--accel none|bvh</c> option shared by the commands that render.</summary>
public static class AccelOption
{
  public static Option<string> Create()
  {
    var o = new Option<string>("--accel")
    {
      Description = "Ray queries: bvh = prepared scene, BVH, allocation-free kernels (default); none = GrCis's faithful path (every query through Intersect, slow)",
      HelpName = "none|bvh",
      DefaultValueFactory = _ => "bvh",
    };
    o.AcceptOnlyFromAmong("bvh", "none");
    return o;
  }

  public static AccelMode Parse(string? value) =>
    value is "none" ? AccelMode.None : AccelMode.Bvh;
}
