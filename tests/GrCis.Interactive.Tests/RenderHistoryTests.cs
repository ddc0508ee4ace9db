using System;
using System.IO;
using System.Linq;
using Rendering.Imaging;
using GrCis.Hosting;

namespace GrCis.Interactive.Tests;

public class RenderHistoryTests
{
  static RenderRecord Record(int i) =>
    new(new FloatImage(2, 2), new RenderSettings { Seed = i }, new RenderStatistics(), $"scene {i}", "", 1.0, true);

  [Fact]
  public void Keeps_the_last_five_and_steps_back_and_forward()
  {
    var h = new RenderHistory();
    Assert.Null(h.Current);
    Assert.Null(h.Back());
    for (int i = 0; i < 7; i++)
      h.Add(Record(i));

    Assert.Equal(new long[] { 2, 3, 4, 5, 6 }, h.Items.Select(r => r.Settings.Seed));
    Assert.Equal(6, h.Current!.Settings.Seed);
    Assert.False(h.CanGoForward);
    Assert.Equal(5, h.Back()!.Settings.Seed);
    Assert.Equal(4, h.Back()!.Settings.Seed);
    Assert.True(h.CanGoForward);
    Assert.Equal(5, h.Forward()!.Settings.Seed);
    h.Back(); h.Back(); h.Back();
    Assert.Null(h.Back());
    Assert.Equal(2, h.Current!.Settings.Seed);
    h.Add(Record(9));
    Assert.Equal(9, h.Current!.Settings.Seed);
  }

  [Fact]
  public void Save_writes_the_display_png_and_never_a_partial_file()
  {
    using var tmp = new TempDir();
    var img = new FloatImage(3, 2);
    img.SetPixel(1, 1, new[] { 1.0, 0.25, 0.0 });
    var h = new RenderHistory();
    Assert.Throws<InvalidOperationException>(() => h.SaveCurrent(tmp.File("none.png")));
    h.Add(new RenderRecord(img, new RenderSettings(), new RenderStatistics(), "s", "", 1.0, true));
    h.SaveCurrent(tmp.File("a.png"));
    Assert.Equal((byte)255, PngFile.Load(tmp.File("a.png")).GetPixel(1, 1).R);
    Assert.Equal(new[] { "a.png" }, Directory.GetFiles(tmp.Path).Select(Path.GetFileName));
  }
}
