using Rendering;

namespace GrCis.Bench.Tests;

/// <summary>
/// The lean probe measures the kernel's generality only if it traces the kernel's ray tree: the same scene, about the
/// same number of rays and hits, about the same picture (its jitter and some rounding differ, so not the same bits).
/// </summary>
public class LeanWhittedProbeTests
{
  [Fact]
  public void The_lean_probe_traces_the_kernels_ray_tree_of_two_spheres()
  {
    const int width = 80, height = 60, grid = 4;
    var scene = new DefaultRayScene();
    Scenes.TwoSpheres(scene, "");
    GrCis.Hosting.FrameResult frame = LeanWhittedBenchmarks.RenderKernel(scene, width, height, grid);
    float[] kernel = frame.Image.Data;
    var probe = new LeanWhittedProbe();
    double[] lean = probe.Render(width, height, grid);

    // Rays: closest-hit and shadow queries alike (the kernel counts both); 4 % apart at 640×480 when this was written.
    long leanRays = probe.Queries + probe.ShadowQueries;
    Assert.InRange((double)leanRays / frame.Statistics.Rays, 0.92, 1.02);
    Assert.True(probe.Queries >= width * height * grid * grid, $"{probe.Queries} queries");
    Assert.InRange((double)probe.Hits / probe.Queries, 0.55, 0.75);

    // The picture: the mean and the mean absolute difference of the linear samples (0.21 and 0.009 when written).
    Assert.Equal(kernel.Length, lean.Length);
    double kernelSum = 0.0, leanSum = 0.0, difference = 0.0;
    for (int i = 0; i < lean.Length; i++)
    {
      kernelSum += kernel[i];
      leanSum += lean[i];
      difference += System.Math.Abs(kernel[i] - lean[i]);
    }
    Assert.InRange(leanSum / kernelSum, 0.97, 1.01);
    Assert.True(difference / lean.Length < 0.02, $"mean absolute difference {difference / lean.Length}");
  }
}
