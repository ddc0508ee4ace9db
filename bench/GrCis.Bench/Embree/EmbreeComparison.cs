using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Threading;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Scene3D;

namespace GrCis.Bench.Embree;

/// <summary>
/// <c>embree [--mesh FILE.obj[.gz]] [--size N] [--rays N] [--threads 1,2] [--repeats N] [--seed S] [--order interleaved|grouped] [--tsv FILE]</c>:
/// the library's ray queries against Intel Embree's on the same rays and the same mesh, in one run. The mesh is
/// placed as <c>grcis bench --mesh</c> places it (centred, box diagonal 3); without <c>--mesh</c>, a procedural
/// torus of 100,000 triangles. Per ray set and thread count, each implementation is timed once per round, the
/// implementations alternating within a round; the median over rounds is reported. Hit or miss must agree ray for
/// ray with Embree's single-ray query (mismatches are counted and printed). The BVH builds are timed too. Ray sets:
/// camera rays with tight framing, incoherent rays (closest hit), segments between random points of the mesh's box,
/// and shadow rays from the surface points the incoherent rays hit to a light outside the mesh (occlusion).
/// </summary>
public static class EmbreeComparison
{
  /// <summary>True when Intel Embree 3's shared library loads on this machine.</summary>
  public static bool IsAvailable => EmbreeNative.IsAvailable;

  /// <summary>The Debian package that ships it.</summary>
  public const string DebianPackage = EmbreeNative.DebianPackage;

  /// <summary>The command: prints the table; 0 on success, 1 for a bad argument or mesh file, 2 without libembree3, 3 when hits disagree.</summary>
  public static int Run(string[] args, TextWriter output, TextWriter error)
  {
    EmbreeOptions options;
    try
    {
      options = EmbreeOptions.Parse(args);
      // Checked before the minutes of measuring, not after.
      if (options.TsvFile != null && Path.GetDirectoryName(Path.GetFullPath(options.TsvFile)) is string folder && !Directory.Exists(folder))
        throw new ArgumentException($"--tsv: the folder {folder} does not exist");
      EmbreeReport report = Measure(options, output);
      if (options.TsvFile != null)
      {
        EmbreeTsv.Write(report, options.MeshFile != null ? Path.GetFileName(options.MeshFile) : "procedural torus",
                        "embree " + string.Join(' ', args.Select(a => a == options.MeshFile ? "<mesh folder>/" + Path.GetFileName(a) : a == options.TsvFile ? Path.GetFileName(a) : a)), options.TsvFile);
        output.WriteLine($"wrote {options.TsvFile}");
      }
      return report.Mismatches == 0 ? 0 : 3;
    }
    catch (EmbreeMissingException e)
    {
      error.WriteLine("embree: " + e.Message);
      return 2;
    }
    catch (Exception e) when (e is MeshFormatException or IOException or UnauthorizedAccessException or ArgumentException)
    {
      error.WriteLine("embree: " + e.Message);
      return 1;
    }
  }

  /// <summary>Runs every measurement of <paramref name="options"/>, writing the table as it goes.</summary>
  public static EmbreeReport Measure(EmbreeOptions options, TextWriter output)
  {
    EmbreeNative.Require();
    SceneBrep mesh = options.MeshFile != null ? ReadPlaced(options.MeshFile) : Placed(ProceduralMesh.Torus(250, 200));
    var (positions, indices, min, max) = Arrays(mesh);
    var report = new EmbreeReport { Triangles = mesh.Triangles, LoadBefore = EmbreeTsv.LoadAverage() };
    output.WriteLine($"mesh: {(options.MeshFile != null ? Path.GetFileName(options.MeshFile) : "procedural torus")}, {mesh.Triangles} triangles; {Environment.ProcessorCount} logical CPUs; median of {options.Repeats} rounds, {(options.ThreadCpu ? "thread CPU time" : "wall time")}");

    // Builds: the library's mesh BVH (large subtrees on the thread pool: all cores) and Embree's MEDIUM (binned SAH) on one thread and on all.
    report.LibraryBuild = Median(options.Repeats, () =>
    {
      var fresh = new TriangleMesh(mesh);
      long allocated = GC.GetTotalAllocatedBytes(true);
      var clock = Stopwatch.StartNew();
      fresh.IntersectFirst(new Vector3d(0, 0, -10), Vector3d.UnitZ, 1.0, out _, out _);   // builds the BVH on first use
      double seconds = clock.Elapsed.TotalSeconds;
      report.LibraryBuildBytes = GC.GetTotalAllocatedBytes(true) - allocated;   // the last round's: pools are warm by then
      return seconds;
    });
    report.EmbreeBuild1 = Median(options.Repeats, () => { using var s = new EmbreeScene(positions, indices, EmbreeNative.BuildQualityMedium, "threads=1"); return s.BuildSeconds; });
    report.EmbreeBuildAll = Median(options.Repeats, () => { using var s = new EmbreeScene(positions, indices, EmbreeNative.BuildQualityMedium, null); return s.BuildSeconds; });
    output.WriteLine($"build: mesh BVH {report.LibraryBuild * 1e3:F1} ms (all cores), {report.LibraryBuildBytes / 1e6:F1} MB allocated; Embree MEDIUM {report.EmbreeBuild1 * 1e3:F1} ms (1 thread), {report.EmbreeBuildAll * 1e3:F1} ms (all threads)");

    using var embree = new EmbreeScene(positions, indices, EmbreeNative.BuildQualityMedium, null);
    var solid = new TriangleMesh(mesh);
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
    root.InsertChild(solid, Matrix4d.Identity);
    PreparedScene scene = PreparedScene.Prepare(root);

    RaySet incoherent = RaySet.Incoherent(min, max, options.Rays, options.Seed);
    RaySet[] sets =
    {
      RaySet.CameraTight(min, max, options.Size),
      incoherent,
      RaySet.SegmentsBetween(min, max, options.Rays, options.Seed + 1),
      RaySet.ShadowFromSurfaces(incoherent, (p0, p1) => solid.IntersectFirst(p0, p1, p1.LengthSquared, out SolidRecord h, out _) ? h.T : double.PositiveInfinity,
                                0.5 * (min + max), (max - min).Length, options.Seed + 2),
    };
    foreach (RaySet rays in sets)
    {
      var queries = new List<(string Name, Func<RayRange> Worker)>();
      if (rays.Segments)
      {
        queries.Add(("Embree rtcOccluded1", () => EmbreeWorker(embree, rays)));
        queries.Add(("TriangleMesh.IntersectFirst, t <= end", () => MeshWorker(solid, rays)));
        queries.Add(("PreparedScene.AnyHit", () => SceneWorker(scene, rays)));
      }
      else
      {
        queries.Add(("Embree rtcIntersect1", () => EmbreeWorker(embree, rays)));
        if (rays.Count % 16 == 0 && rays.Name.StartsWith("camera", StringComparison.Ordinal))
          queries.Add(("Embree rtcIntersect16", () => EmbreePacketWorker(embree, rays)));
        queries.Add(("TriangleMesh.IntersectFirst", () => MeshWorker(solid, rays)));
        queries.Add(("PreparedScene.FirstHit", () => SceneWorker(scene, rays)));
      }

      // Agreement, ray for ray, against Embree's single-ray query.
      var reference = new bool[rays.Count];
      queries[0].Worker()(0, rays.Count, reference);
      int referenceHits = reference.Count(h => h);
      output.WriteLine();
      output.WriteLine($"{rays.Name}: {rays.Count} rays, {100.0 * referenceHits / rays.Count:F1} % hit (Embree)");
      var agreement = new int[queries.Count];
      for (int q = 1; q < queries.Count; q++)
      {
        var mine = new bool[rays.Count];
        queries[q].Worker()(0, rays.Count, mine);
        for (int i = 0; i < rays.Count; i++)
          if (mine[i] != reference[i])
          {
            if (agreement[q]++ < 3)
              output.WriteLine($"  mismatch: {queries[q].Name} says {(mine[i] ? "hit" : "miss")} for ray {i}: o = ({rays.Ox[i]:R}, {rays.Oy[i]:R}, {rays.Oz[i]:R}), d = ({rays.Dx[i]:R}, {rays.Dy[i]:R}, {rays.Dz[i]:R})");
          }
      }

      foreach (int threads in options.Threads)
      {
        var times = new List<double>[queries.Count];
        for (int q = 0; q < queries.Count; q++)
          times[q] = new List<double>();
        for (int k = 0; k < options.Repeats * queries.Count; k++)
        {
          // Interleaved: round by round, every query in turn; grouped: every round of a query, then the next query.
          int q = options.Grouped ? k / options.Repeats : k % queries.Count;
          times[q].Add(Time(queries[q].Worker, rays.Count, threads, options.ThreadCpu));
        }
        for (int q = 0; q < queries.Count; q++)
        {
          double mrays = rays.Count / Median(times[q]) / 1e6;
          var row = new EmbreeRow(rays.Name, queries[q].Name, threads, mrays, referenceHits, agreement[q]);
          report.Rows.Add(row);
          double embreeMrays = report.ReferenceMrays(row);
          output.WriteLine($"  {queries[q].Name,-40} {threads} thread{(threads > 1 ? "s" : " ")}: {mrays,8:F2} Mrays/s  ({embreeMrays / mrays:F2}x Embree's time){(q > 0 ? $", {agreement[q]} mismatches" : "")}");
        }
      }
    }
    return report;
  }

  /// <summary>Traces rays [start, end), counting hits; writes hit or miss per ray into <c>hits</c> when given.</summary>
  public delegate int RayRange(int start, int end, bool[]? hits);

  static unsafe RayRange EmbreeWorker(EmbreeScene embree, RaySet r)
  {
    // Embree's ray structures are 16-byte aligned: one native buffer per worker (freed with the process's end of run).
    var rh = (EmbreeNative.RayHit*)NativeMemory.AlignedAlloc((nuint)sizeof(EmbreeNative.RayHit), 64);
    return (start, end, hits) =>
    {
      int count = 0;
      for (int i = start; i < end; i++)
      {
        rh->Ray = new EmbreeNative.Ray
        {
          OrgX = (float)r.Ox[i],
          OrgY = (float)r.Oy[i],
          OrgZ = (float)r.Oz[i],
          TNear = (float)r.TNear[i],
          DirX = (float)r.Dx[i],
          DirY = (float)r.Dy[i],
          DirZ = (float)r.Dz[i],
          TFar = (float)r.TFar[i],
          Mask = uint.MaxValue,
        };
        bool hit = r.Segments ? embree.Occluded(&rh->Ray) : embree.Intersect(rh);
        if (hit)
          count++;
        if (hits != null)
          hits[i] = hit;
      }
      return count;
    };
  }

  static unsafe RayRange EmbreePacketWorker(EmbreeScene embree, RaySet r)
  {
    byte* buffer = (byte*)NativeMemory.AlignedAlloc((nuint)(sizeof(EmbreeNative.RayHit16) + 64), 64);
    var packet = (EmbreeNative.RayHit16*)buffer;
    int* valid = (int*)(buffer + sizeof(EmbreeNative.RayHit16));
    return (start, end, hits) =>
    {
      int count = 0;
      for (int p = start; p < end; p += 16)
      {
        int n = Math.Min(16, end - p);
        for (int k = 0; k < n; k++)
        {
          int i = p + k;
          packet->OrgX[k] = (float)r.Ox[i]; packet->OrgY[k] = (float)r.Oy[i]; packet->OrgZ[k] = (float)r.Oz[i];
          packet->DirX[k] = (float)r.Dx[i]; packet->DirY[k] = (float)r.Dy[i]; packet->DirZ[k] = (float)r.Dz[i];
          packet->TNear[k] = (float)r.TNear[i]; packet->TFar[k] = (float)r.TFar[i];
          packet->Time[k] = 0f; packet->Mask[k] = uint.MaxValue; packet->Id[k] = (uint)k; packet->Flags[k] = 0;
        }
        embree.Intersect16(packet, valid, n);
        for (int k = 0; k < n; k++)
        {
          bool hit = packet->GeomId[k] != EmbreeNative.InvalidGeometryId;
          if (hit)
            count++;
          if (hits != null)
            hits[p + k] = hit;
        }
      }
      return count;
    };
  }

  static RayRange MeshWorker(TriangleMesh mesh, RaySet r) => (start, end, hits) =>
  {
    int count = 0;
    for (int i = start; i < end; i++)
    {
      var p0 = new Vector3d(r.Ox[i], r.Oy[i], r.Oz[i]);
      var p1 = new Vector3d(r.Dx[i], r.Dy[i], r.Dz[i]);
      bool hit = mesh.IntersectFirst(p0, p1, p1.LengthSquared, out SolidRecord h, out _) && h.T <= r.TFar[i];
      if (hit)
        count++;
      if (hits != null)
        hits[i] = hit;
    }
    return count;
  };

  static RayRange SceneWorker(PreparedScene scene, RaySet r)
  {
    var reuse = new Intersection();
    return (start, end, hits) =>
    {
      int count = 0;
      for (int i = start; i < end; i++)
      {
        var p0 = new Vector3d(r.Ox[i], r.Oy[i], r.Oz[i]);
        var p1 = new Vector3d(r.Dx[i], r.Dy[i], r.Dz[i]);
        bool hit = r.Segments ? scene.AnyHit(p0, p1) : scene.FirstHit(p0, p1, reuse, HitData.Surface) != null;
        if (hit)
          count++;
        if (hits != null)
          hits[i] = hit;
      }
      return count;
    };
  }

  /// <summary>
  /// Seconds to trace all rays on <paramref name="threads"/> threads, each with its own worker, taking chunks of 256 rays
  /// (a multiple of 16); with <paramref name="threadCpu"/> (one thread), the processor time of the calling thread.
  /// </summary>
  static double Time(Func<RayRange> worker, int count, int threads, bool threadCpu = false)
  {
    const int chunk = 256;
    int next = 0;
    var workers = new RayRange[threads];
    for (int t = 0; t < threads; t++)
      workers[t] = worker();
    void Work(RayRange w)
    {
      for (int start; (start = Interlocked.Add(ref next, chunk) - chunk) < count;)
        w(start, Math.Min(count, start + chunk), null);
    }
    double cpu0 = threadCpu ? ThreadCpuSeconds() : 0.0;
    var clock = Stopwatch.StartNew();
    var running = new Thread[threads - 1];
    for (int t = 1; t < threads; t++)
    {
      RayRange w = workers[t];
      running[t - 1] = new Thread(() => Work(w)) { IsBackground = true };
      running[t - 1].Start();
    }
    Work(workers[0]);
    foreach (Thread t in running)
      t.Join();
    return threadCpu ? ThreadCpuSeconds() - cpu0 : clock.Elapsed.TotalSeconds;
  }

  [StructLayout(LayoutKind.Sequential)]
  struct Timespec
  {
    public long Seconds, Nanoseconds;
  }

  [DllImport("libc", EntryPoint = "clock_gettime")]
  static extern int ClockGetTime(int clock, out Timespec time);

  /// <summary>Processor time of the calling thread (Linux CLOCK_THREAD_CPUTIME_ID).</summary>
  static double ThreadCpuSeconds()
  {
    const int ThreadCpuClock = 3;
    if (ClockGetTime(ThreadCpuClock, out Timespec t) != 0)
      throw new InvalidOperationException("clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    return t.Seconds + 1e-9 * t.Nanoseconds;
  }

  static double Median(int repeats, Func<double> measure)
  {
    var values = new List<double>();
    for (int i = 0; i < repeats; i++)
      values.Add(measure());
    return Median(values);
  }

  static double Median(List<double> values)
  {
    values.Sort();
    int n = values.Count;
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  }

  /// <summary>Reads an OBJ file (gzip-compressed or not) and places it as <c>grcis bench --mesh</c> does.</summary>
  static SceneBrep ReadPlaced(string path)
  {
    var mesh = new SceneBrep();
    new WavefrontObj().ReadBrep(path, mesh);
    return Placed(mesh);
  }

  /// <summary>Centred at the origin and scaled to box diagonal 3 (Scenes.MeshScene without its tilt), in the vertices themselves.</summary>
  static SceneBrep Placed(SceneBrep mesh)
  {
    float diameter = mesh.GetDiameter(out Vector3 center);
    double scale = diameter > 0f ? 3.0 / diameter : 1.0;
    for (int v = 0; v < mesh.Vertices; v++)
      mesh.SetVertex(v, (Vector3)(((Vector3d)mesh.GetVertex(v) - (Vector3d)center) * scale));
    return mesh;
  }

  static (float[] Positions, int[] Indices, Vector3d Min, Vector3d Max) Arrays(SceneBrep mesh)
  {
    var positions = new float[3 * mesh.Vertices];
    Vector3d min = Vector3d.PositiveInfinity, max = Vector3d.NegativeInfinity;
    for (int v = 0; v < mesh.Vertices; v++)
    {
      Vector3 p = mesh.GetVertex(v);
      positions[3 * v] = p.X; positions[3 * v + 1] = p.Y; positions[3 * v + 2] = p.Z;
      min = Vector3d.ComponentMin(min, p);
      max = Vector3d.ComponentMax(max, p);
    }
    var indices = new int[3 * mesh.Triangles];
    for (int t = 0; t < mesh.Triangles; t++)
    {
      mesh.GetTriangleVertices(t, out int a, out int b, out int c);
      indices[3 * t] = a; indices[3 * t + 1] = b; indices[3 * t + 2] = c;
    }
    return (positions, indices, min, max);
  }
}
