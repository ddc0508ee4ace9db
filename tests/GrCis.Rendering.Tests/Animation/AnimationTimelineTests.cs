using System;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

public class AnimationTimelineTests
{
  [Theory]
  [InlineData(0.0, 10.0, 25.0, 251)]
  [InlineData(0.0, 1.0, 30.0, 31)]
  [InlineData(2.0, 2.0, 24.0, 1)]
  [InlineData(0.0, 1.1, 3.0, 4)]   // 1.1 s at 3 fps: the end falls between frames, last at 1.0
  [InlineData(0.0, 1.2, 3.0, 5)]   // within half a frame of 1.333: included, as GrCis does
  public void Frame_count_includes_both_ends(double start, double end, double fps, int frames)
  {
    var tl = new AnimationTimeline(start, end, fps);
    Assert.Equal(frames, tl.FrameCount);
    Assert.Equal(start, tl.FrameTime(0));
  }

  [Fact]
  public void Last_frame_is_exactly_at_the_end()
  {
    var tl = new AnimationTimeline(0.0, 10.0, 25.0);
    Assert.Equal(10.0, tl.FrameTime(tl.FrameCount - 1));
  }

  [Fact]
  public void Frame_times_are_computed_not_accumulated()
  {
    var tl = new AnimationTimeline(0.0, 1000.0 / 30.0, 30.0);
    Assert.Equal(1001, tl.FrameCount);
    double accumulated = 0.0;
    bool accumulationDrifted = false;
    for (int k = 0; k < tl.FrameCount; k++)
    {
      Assert.Equal(k / 30.0, tl.FrameTime(k));
      accumulationDrifted |= accumulated != k / 30.0;
      accumulated += 1.0 / 30.0;
    }
    Assert.True(accumulationDrifted);   // the naive loop would have drifted
  }

  [Fact]
  public void Bad_ranges_are_rejected_with_a_message()
  {
    Assert.Throws<ArgumentOutOfRangeException>(() => new AnimationTimeline(1.0, 0.0, 25.0));
    Assert.Throws<ArgumentOutOfRangeException>(() => new AnimationTimeline(0.0, 1.0, 0.0));
    Assert.Throws<ArgumentOutOfRangeException>(() => new AnimationTimeline(0.0, 1.0, 25.0).FrameTime(26));
  }
}
