using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using OpenTK.Mathematics;
using Rendering;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class AnimationTests
{
  /// <summary>A background whose red channel is the scene time.</summary>
  sealed class TimeBackground : IBackground, ITimeDependent
  {
    public double Start { get; set; }
    public double End { get; set; } = 1;
    public double Time { get; set; }
    public object Clone() => MemberwiseClone();
    public long GetColor(Vector3d p1, double[] color)
    {
      color[0] = Time;
      color[1] = color[2] = 0;
      return 1;
    }
  }

  static IRayScene Scene() => new AnimatedRayScene
  {
    Background = new TimeBackground(),
    Camera = new StaticCamera(Vector3d.Zero, Vector3d.UnitZ, 60),
    Intersectable = new CSGInnerNode(SetOperation.Union),
    Sources = new LinkedList<ILightSource>(),
  };

  [Fact]
  public void Still_at_a_chosen_time()
  {
    RenderJob job = RenderJob.Create(Scene(), new RenderSettings { Width = 8, Height = 8, Time = 0.5 });
    var image = Rendering.Execution.TileRenderer.Render(job.Scene, job.ImageFunction, job.Renderer, job.Options);
    Assert.Equal(0.5, image.GetPixel(3, 3)[0]);
  }

  [Fact]
  public async Task Animation_renders_every_frame_time_saves_frames_and_estimates_time_left()
  {
    using var tmp = new TempDir();
    RenderJob job = RenderJob.Create(Scene(), new RenderSettings { Width = 8, Height = 8 });
    var run = new AnimationRun(job, new AnimationTimeline(0, 1, 4));
    var frames = new List<FrameRenderedEventArgs>();
    run.FrameRendered += (_, e) => frames.Add(e);

    int done = await run.RunAsync(Path.Combine(tmp.Path, "out##.png"));

    Assert.Equal(5, done);
    Assert.Equal(new[] { 0, 0.25, 0.5, 0.75, 1.0 }, frames.Select(f => f.Time));
    Assert.Equal(new[] { 0, 0.25, 0.5, 0.75, 1.0 }, frames.Select(f => (double)f.Image.GetPixel(4, 4)[0]));
    Assert.Equal(TimeSpan.Zero, frames[^1].Eta);
    Assert.All(frames, f => Assert.Equal(5, f.FramesTotal));
    Assert.Equal(Enumerable.Range(0, 5).Select(k => $"out0{k}.png"), Directory.GetFiles(tmp.Path).Select(Path.GetFileName).Order());
  }

  [Fact]
  public void Frame_file_names_fill_the_hash_run()
  {
    Assert.Equal("f/out0042.png", AnimationRun.FrameFileName("f/out####.png", 42));
    Assert.Equal("out0007.png", AnimationRun.FrameFileName("out.png", 7));
  }
}
