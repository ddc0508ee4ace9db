using System;
using Rendering;
using Rendering.Distributed;
using Rendering.Accel;

namespace GrCis.Hosting.Tests;

/// <summary>
/// The one precedence rule of every front end: a setting the user gave, then the script's choice, then the default.
/// </summary>
public class PrecedenceTests
{
  static readonly RenderSettings Defaults = new();

  /// <summary>An image function of another class than RayTracing (a script's own).</summary>
  sealed class Flat : IImageFunction
  {
    public double Width { get; set; }
    public double Height { get; set; }

    public long GetSample(double x, double y, double[] color) => 0L;
  }

  [Fact]
  public void Without_a_script_the_requested_settings_are_used_as_they_are()
  {
    var requested = Defaults with { Width = 320, Height = 200, SamplesPerPixel = 9 };
    RenderPlan plan = Precedence.Resolve(requested, GivenSettings.None, null);
    Assert.Same(requested, plan.Settings);
    Assert.Null(plan.ImageFunction);
    Assert.Null(plan.Synthesizer);
    Assert.Empty(plan.Notes);
  }

  [Fact]
  public void Reflection_and_refraction_switches_given_to_path_tracing_are_noted_as_not_applying()
  {
    // Chosen by --algorithm path (no script) or by a script's own PathTracing: the switches are named, not swallowed.
    var requested = Defaults with { Algorithm = RenderAlgorithm.Path, Reflections = false, Refractions = false };
    RenderPlan plain = Precedence.Resolve(requested, GivenSettings.Algorithm | GivenSettings.Reflections | GivenSettings.Refractions, null);
    string note = Assert.Single(plain.Notes);
    Assert.Contains("reflections/refractions given: path tracing", note);

    var script = new ScriptChoices { ImageFunction = new PathTracing() };
    RenderPlan scripted = Precedence.Resolve(Defaults with { Refractions = false }, GivenSettings.Refractions, script);
    Assert.Contains(scripted.Notes, n => n.StartsWith("refractions given: path tracing", StringComparison.Ordinal));

    // Shadows it follows; Whitted follows all three: no note.
    Assert.Empty(Precedence.Resolve(requested with { Shadows = false, Reflections = true, Refractions = true }, GivenSettings.Shadows, null).Notes);
    Assert.Empty(Precedence.Resolve(Defaults with { Reflections = false }, GivenSettings.Reflections, null).Notes);
  }

  [Fact]
  public void The_scripts_size_and_supersampling_win_over_defaults_but_not_over_given_values()
  {
    var script = new ScriptChoices { Width = 100, Height = 80, SamplesPerPixel = 16 };

    RenderSettings byScript = Precedence.Resolve(Defaults, GivenSettings.None, script).Settings;
    Assert.Equal((100, 80, 16), (byScript.Width, byScript.Height, byScript.SamplesPerPixel));

    var requested = Defaults with { Width = 64, Height = 48, SamplesPerPixel = 4 };
    RenderSettings byUser = Precedence.Resolve(requested, GivenSettings.Size | GivenSettings.SamplesPerPixel, script).Settings;
    Assert.Equal((64, 48, 4), (byUser.Width, byUser.Height, byUser.SamplesPerPixel));

    // Only the width set by the script: the height stays.
    RenderSettings half = Precedence.Resolve(Defaults, GivenSettings.None, new ScriptChoices { Width = 200 }).Settings;
    Assert.Equal((200, Defaults.Height), (half.Width, half.Height));
  }

  [Theory]
  [InlineData(-5, 480, null)]
  [InlineData(640, 0, null)]
  [InlineData(null, null, 0)]
  [InlineData(null, null, RenderSettings.MaxSamplesPerPixel + 1)]
  public void A_script_asking_for_an_unusable_size_or_sample_count_is_named_in_the_message(int? width, int? height, int? spp)
  {
    var script = new ScriptChoices { Name = "scene.cs", Width = width, Height = height, SamplesPerPixel = spp };
    var e = Assert.Throws<ScriptChoiceException>(() => Precedence.Resolve(Defaults, GivenSettings.None, script));
    Assert.StartsWith("scene.cs: the script asks for", e.Message);
  }

  [Fact]
  public void The_scripts_renderer_is_sized_and_gives_its_gamma_unless_sampling_or_gamma_is_given()
  {
    var synth = new SupersamplingImageSynthesizer { Supersampling = 4, Gamma = 1.8 };
    RenderPlan plan = Precedence.Resolve(Defaults, GivenSettings.None, new ScriptChoices { Width = 50, Height = 40, Renderer = synth });
    Assert.Same(synth, plan.Synthesizer);
    Assert.Equal((50, 40), (synth.Width, synth.Height));
    Assert.Equal(1.8, plan.Settings.Gamma);

    RenderPlan gammaGiven = Precedence.Resolve(Defaults with { Gamma = 1.0 }, GivenSettings.Gamma, new ScriptChoices { Renderer = synth });
    Assert.Equal(1.0, gammaGiven.Settings.Gamma);

    RenderPlan sppGiven = Precedence.Resolve(Defaults with { SamplesPerPixel = 9 }, GivenSettings.SamplesPerPixel,
      new ScriptChoices { Renderer = synth }, s => s == Setting.SamplesPerPixel ? "--spp" : "--jitter");
    Assert.Null(sppGiven.Synthesizer);
    Assert.IsType<SupersamplingImageSynthesizer>(sppGiven.CreateSynthesizer());
    Assert.Equal("--spp/--jitter given: the script's renderer SupersamplingImageSynthesizer is not used", Assert.Single(sppGiven.Notes));
  }

  [Fact]
  public void Given_switches_apply_to_the_scripts_ray_tracer_and_the_rest_of_its_settings_stay()
  {
    var rt = new RayTracing { DoShadows = true, DoReflections = false, TransparentShadows = true, MaxLevel = 3 };
    RenderPlan plan = Precedence.Resolve(Defaults with { Shadows = false, Reflections = true }, GivenSettings.Shadows,
      new ScriptChoices { ImageFunction = rt });
    Assert.Same(rt, plan.ImageFunction);
    Assert.False(rt.DoShadows);               // given
    Assert.False(rt.DoReflections);           // not given: the script's value
    Assert.True(rt.TransparentShadows);
    Assert.Equal(3, rt.MaxLevel);

    // The demo gives all three switches (GrCis's check boxes): they set the script's tracer both ways.
    Precedence.Resolve(Defaults, GivenSettings.Switches, new ScriptChoices { ImageFunction = rt });
    Assert.True(rt.DoShadows && rt.DoReflections && rt.DoRefractions);
  }

  [Fact]
  public void A_function_of_another_class_is_replaced_only_when_a_given_switch_turns_something_off()
  {
    var flat = new Flat();
    Assert.Same(flat, Precedence.Resolve(Defaults, GivenSettings.Switches, new ScriptChoices { ImageFunction = flat }).ImageFunction);

    RenderPlan off = Precedence.Resolve(Defaults with { Refractions = false }, GivenSettings.Refractions, new ScriptChoices { ImageFunction = flat });
    Assert.Null(off.ImageFunction);
    RayTracing replacement = Assert.IsType<RayTracing>(off.CreateImageFunction());
    Assert.False(replacement.DoRefractions);
    Assert.Contains("image function Flat is replaced by RayTracing", Assert.Single(off.Notes));
  }

  [Fact]
  public void The_query_mode_is_applied_to_the_scripts_function_only_when_given()
  {
    var rt = new RayTracing { Accel = AccelMode.None };
    Precedence.Resolve(Defaults, GivenSettings.None, new ScriptChoices { ImageFunction = rt });
    Assert.Equal(AccelMode.None, rt.Accel);
    Precedence.Resolve(Defaults with { Accel = AccelMode.Bvh }, GivenSettings.Accel, new ScriptChoices { ImageFunction = rt });
    Assert.Equal(AccelMode.Bvh, rt.Accel);
  }

  [Fact]
  public void The_scripts_time_counts_unless_a_time_is_given()
  {
    Assert.Equal(2.5, Precedence.Resolve(Defaults, GivenSettings.None, new ScriptChoices { Time = 2.5 }).Settings.Time);
    Assert.Equal(1.0, Precedence.Resolve(Defaults with { Time = 1.0 }, GivenSettings.Time, new ScriptChoices { Time = 2.5 }).Settings.Time);
  }

  [Fact]
  public void A_non_image_synthesizer_renderer_is_noted_and_replaced_by_the_default()
  {
    RenderPlan plan = Precedence.Resolve(Defaults, GivenSettings.None, new ScriptChoices { Renderer = new OddRenderer() });
    Assert.Null(plan.Synthesizer);
    Assert.Contains("OddRenderer is not an ImageSynthesizer", Assert.Single(plan.Notes));
  }

  sealed class OddRenderer : IRenderer
  {
    public IImageFunction? ImageFunction { get; set; }
    public int Width { get; set; }
    public int Height { get; set; }
    public double Gamma { get; set; }
    public int Adaptive { get; set; }
    public MathSupport.Progress? ProgressData { get; set; }

    public void RenderPixel(int x, int y, double[] color) { }

    public void RenderRectangle(Rendering.Imaging.FloatImage image, int x1, int y1, int x2, int y2) { }
  }

  [Fact]
  public void A_given_algorithm_replaces_the_scripts_image_function_with_a_note()
  {
    var script = new ScriptChoices { ImageFunction = new DistributedRayTracing() };
    RenderPlan kept = Precedence.Resolve(Defaults with { Algorithm = RenderAlgorithm.Path }, GivenSettings.None, script);
    Assert.IsType<DistributedRayTracing>(kept.ImageFunction);

    RenderPlan replaced = Precedence.Resolve(Defaults with { Algorithm = RenderAlgorithm.Path }, GivenSettings.Algorithm, script);
    Assert.Null(replaced.ImageFunction);
    Assert.IsType<PathTracing>(replaced.CreateImageFunction());
    Assert.Contains(replaced.Notes, n => n.Contains("DistributedRayTracing") && n.Contains("PathTracing"));

    // Asking for what the script already chose keeps the script's object and its settings, without a note.
    var own = new PathTracing { MaxLevel = 5 };
    RenderPlan same = Precedence.Resolve(Defaults with { Algorithm = RenderAlgorithm.Path }, GivenSettings.Algorithm, new ScriptChoices { ImageFunction = own });
    Assert.Same(own, same.ImageFunction);
    Assert.Empty(same.Notes);
  }

  [Fact]
  public void A_job_uses_the_flags_it_is_given_and_by_default_leaves_the_scripts_function()
  {
    var settings = new RenderSettings { Width = 8, Height = 6, Algorithm = RenderAlgorithm.Path };
    var script = new ScriptChoices { ImageFunction = new DistributedRayTracing() };
    Assert.IsType<DistributedRayTracing>(RenderJob.Create(Scenes.Create("Two spheres", ""), settings, choices: script).ImageFunction);
    RenderJob given = RenderJob.Create(Scenes.Create("Two spheres", ""), settings, choices: script, given: RenderJob.Given | GivenSettings.Algorithm);
    Assert.IsType<PathTracing>(given.ImageFunction);
    Assert.Contains(given.Notes, n => n.Contains("PathTracing"));
  }

  [Theory]
  [InlineData(RenderAlgorithm.RayTracing, typeof(RayTracing))]
  [InlineData(RenderAlgorithm.Distributed, typeof(DistributedRayTracing))]
  [InlineData(RenderAlgorithm.Path, typeof(PathTracing))]
  public void The_algorithm_setting_selects_the_image_function_with_the_switches_applied(RenderAlgorithm algorithm, Type expected)
  {
    RayTracing f = (Defaults with { Algorithm = algorithm, Shadows = false }).CreateImageFunction();
    Assert.IsType(expected, f);
    Assert.False(f.DoShadows);
  }
}
