using System;
using System.Linq;
using Rendering;
using Rendering.Execution;
using Rendering.Imaging;

namespace GrCis.Scripting.Tests;

/// <summary>
/// A 049-style homework that reads and writes GrCis's <c>MT</c> statics the ways GrCis code does (<c>MT.rnd</c>,
/// <c>MT.rank</c>/<c>MT.total</c>, <c>MT.x</c>, compound assignments) compiles against <c>MT</c>'s properties over the
/// worker context and renders the same picture on any number of threads.
/// </summary>
public sealed class MtFacadeModuleTests : IDisposable
{
  readonly ScratchFolder scratch = new("grcis-mt-");

  public void Dispose() => scratch.Dispose();

  const string Tracer = """
    using System;
    using OpenTK;
    using MathSupport;
    using Rendering;

    namespace Homework049
    {
      /// Jitters each sample's colour by the thread's generator, stratified by the sample's rank as GrCis's hidden sampling was.
      public class NoisyRayTracing : RayTracing
      {
        public NoisyRayTracing () : base() { }

        public override long shade (int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
        {
          long hash = base.shade(depth, importance, ref p0, ref p1, color);
          if (depth > 0)
            return hash;
          RandomJames rnd = MT.rnd;
          double u = (MT.rank + rnd.UniformNumber()) / Math.Max(MT.total, 1);
          int saved = MT.x;
          MT.x += 0;
          MT.doubleX = MT.doubleX;
          color[0] += 0.2 * u + 0.0 * (MT.x - saved) + 0.0 * MT.threadID;
          return hash;
        }
      }
    }
    """;

  [Fact]
  public void A_module_using_MT_the_GrCis_way_compiles_and_renders_the_same_on_1_and_3_threads()
  {
    scratch.Write("NoisyRayTracing.cs", Tracer);
    string script = scratch.Write("Scene.cs", """
      using Homework049;

      Scenes.FiveBalls(scene);
      context[PropertyName.CTX_ALGORITHM] = new NoisyRayTracing();
      """);

    using var host = new ScriptHost();
    host.AddModule(scratch.Path);
    ScriptScene run = host.Load(script);
    var rt = (RayTracing)run.Algorithm!;

    FloatImage Render(int threads) => TileRenderer.Render(run.Scene, rt,
      new SupersamplingImageSynthesizer { Width = 32, Height = 24, Supersampling = 4 }, new RenderOptions { Threads = threads, Seed = 4, TileSize = 8 });
    FloatImage one = Render(1), three = Render(3);
    Assert.Equal(one.Data, three.Data);

    // The module's noise is there: the red band differs from plain ray tracing's.
    FloatImage plain = TileRenderer.Render(run.Scene, new RayTracing(),
      new SupersamplingImageSynthesizer { Width = 32, Height = 24, Supersampling = 4 }, new RenderOptions { Threads = 1, Seed = 4 });
    Assert.True(Enumerable.Range(0, one.Data.Length / 3).Count(i => one.Data[3 * i] != plain.Data[3 * i]) > 32 * 24 / 2);
  }
}
