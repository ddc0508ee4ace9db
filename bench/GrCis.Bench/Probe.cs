using System;
using System.Diagnostics;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Bench;

/// <summary>Primary-ray-only timing of the prepared scene (where does the time go).</summary>
internal static class Probe
{
  public static int Run()
  {
    IRayScene scene = TestScenes.Flake9(4);
    for (int rep = 0; rep < 3; rep++)
    {
      var sw = Stopwatch.StartNew();
      PreparedScene ps = PreparedScene.Prepare(scene.Intersectable);
      Console.WriteLine($"prepare {sw.Elapsed.TotalMilliseconds:F1} ms");
      ICamera cam = scene.Camera!;
      cam.Width = 640;
      cam.Height = 480;
      sw.Restart();
      int hits = 0;
      long alloc0 = GC.GetAllocatedBytesForCurrentThread();
      for (int y = 0; y < 480; y++)
        for (int x = 0; x < 640; x++)
        {
          cam.GetRay(x + 0.5, y + 0.5, out Vector3d p0, out Vector3d p1);
          if (ps.FirstHit(p0, p1) != null)
            hits++;
        }
      Console.WriteLine($"primary FirstHit: {sw.Elapsed.TotalMilliseconds:F0} ms for 307200 rays ({hits} hits), {(GC.GetAllocatedBytesForCurrentThread() - alloc0) / 307200.0:F0} B/ray");
      sw.Restart();
      int occ = 0;
      for (int y = 0; y < 480; y++)
        for (int x = 0; x < 640; x++)
        {
          cam.GetRay(x + 0.5, y + 0.5, out Vector3d p0, out Vector3d p1);
          if (ps.Occluded(p0, p1 * 20))
            occ++;
        }
      Console.WriteLine($"occlusion: {sw.Elapsed.TotalMilliseconds:F0} ms ({occ} occluded)");
    }
    return 0;
  }
}
