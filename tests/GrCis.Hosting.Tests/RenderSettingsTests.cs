using Rendering;
using Rendering.Accel;

namespace GrCis.Hosting.Tests;

public class RenderSettingsTests
{
  [Theory]
  [InlineData(0, 480, 1, 1.0, 0, 2.2, Setting.Size)]
  [InlineData(640, 480, 0, 1.0, 0, 2.2, Setting.SamplesPerPixel)]
  [InlineData(640, 480, RenderSettings.MaxSamplesPerPixel + 1, 1.0, 0, 2.2, Setting.SamplesPerPixel)]
  [InlineData(640, 480, 4, 1.5, 0, 2.2, Setting.Jitter)]
  [InlineData(640, 480, 4, double.NaN, 0, 2.2, Setting.Jitter)]
  [InlineData(640, 480, 4, 1.0, -1, 2.2, Setting.Threads)]
  [InlineData(640, 480, 4, 1.0, 0, 0.0, Setting.Gamma)]
  [InlineData(640, 480, 4, 1.0, 0, double.PositiveInfinity, Setting.Gamma)]
  public void A_value_out_of_range_names_its_setting(int w, int h, int spp, double jitter, int threads, double gamma, Setting bad)
  {
    var s = new RenderSettings { Width = w, Height = h, SamplesPerPixel = spp, Jitter = jitter, Threads = threads, Gamma = gamma };
    var e = Assert.Throws<InvalidSettingException>(() => s.Validate());
    Assert.Equal(bad, e.Setting);
    Assert.False(string.IsNullOrEmpty(e.Rule));
  }

  [Theory]
  [InlineData(1, 1)]
  [InlineData(4, 4)]
  [InlineData(5, 9)]
  [InlineData(16, 16)]
  [InlineData(17, 25)]
  public void Supersampling_rounds_up_to_a_square_grid(int spp, int effective)
  {
    var s = new RenderSettings { SamplesPerPixel = spp };
    Assert.Equal(effective, s.EffectiveSamplesPerPixel);
    Assert.Equal(effective, s.CreateSynthesizer().SamplesPerPixel);
  }

  [Fact]
  public void Objects_from_the_settings_carry_every_setting()
  {
    var s = new RenderSettings { Width = 33, Height = 21, SamplesPerPixel = 4, Jitter = 0.25, Gamma = 1.0,
                                 Shadows = false, Refractions = false, Accel = AccelMode.None, Threads = 3, Seed = 9, TileSize = 7 };
    var synth = Assert.IsType<SupersamplingImageSynthesizer>(s.CreateSynthesizer());
    Assert.Equal((33, 21, 0.25, 1.0), (synth.Width, synth.Height, synth.Jittering, synth.Gamma));
    RayTracing rt = s.CreateImageFunction();
    Assert.Equal((false, true, false, AccelMode.None), (rt.DoShadows, rt.DoReflections, rt.DoRefractions, rt.Accel));
    var options = s.ToRenderOptions(frame: 5);
    Assert.Equal((3, 7, 9L, 5), (options.Threads, options.TileSize, options.Seed, options.Frame));
  }
}
