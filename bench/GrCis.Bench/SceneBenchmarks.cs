using BenchmarkDotNet.Attributes;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Bench;

/// <summary>BVH traversal and one shaded sample on the 7,381-sphere flake (per-ray costs, 1,024 rays per op).</summary>
[MemoryDiagnoser]
public class SceneBenchmarks
{
  const int Side = 32;
  IRayScene scene = null!;
  PreparedScene prepared = null!;
  RayTracing tracer = null!;
  readonly Vector3d[] origins = new Vector3d[Side * Side];
  readonly Vector3d[] dirs = new Vector3d[Side * Side];
  readonly double[] color = new double[3];

  [GlobalSetup]
  public void Setup()
  {
    var sc = new DefaultRayScene();
    Scenes.SphereFlake9(sc, 4);   // the real Sphere and Plane solids
    scene = sc;
    prepared = PreparedScene.Prepare(scene.Intersectable);
    tracer = new RayTracing(scene);
    tracer.Width = 640;
    tracer.Height = 480;
    tracer.Prepare(scene);
    MT.SetRendering(scene, tracer, null);
    // A 32×32 grid of primary rays over the flake's part of the image.
    for (int j = 0; j < Side; j++)
      for (int i = 0; i < Side; i++)
      {
        scene.Camera!.GetRay(200 + 8 * i + 0.5, 60 + 8 * j + 0.5, out Vector3d o, out Vector3d d);
        origins[j * Side + i] = o;
        dirs[j * Side + i] = d;
      }
  }

  [Benchmark(OperationsPerInvoke = Side * Side)]
  public int Bvh_closest_hit()
  {
    int hits = 0;
    for (int k = 0; k < origins.Length; k++)
      if (prepared.FirstHit(origins[k], dirs[k]) != null)
        hits++;
    return hits;
  }

  [Benchmark(OperationsPerInvoke = Side * Side)]
  public int Bvh_any_hit()
  {
    int hits = 0;
    for (int k = 0; k < origins.Length; k++)
      if (prepared.Occluded(origins[k], dirs[k] * 20.0))
        hits++;
    return hits;
  }

  [Benchmark(OperationsPerInvoke = Side * Side)]
  public double Shaded_sample()
  {
    double sum = 0.0;
    for (int j = 0; j < Side; j++)
      for (int i = 0; i < Side; i++)
      {
        MT.StartPixel(200 + 8 * i, 60 + 8 * j, 1);
        tracer.GetSample(200 + 8 * i + 0.5, 60 + 8 * j + 0.5, color);
        sum += color[0];
      }
    return sum;
  }
}
