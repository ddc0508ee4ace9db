using System.CommandLine;
using GrCis.Cli.Jobs;
using GrCis.Hosting;

namespace GrCis.Cli.Commands;

/// <summary>The options that shape one rendered image (size, sampling, threads, seed, gamma, switches), for commands that render.</summary>
public sealed class RenderOptionSet
{
  readonly Option<string> size = new("--size", "-s")
  {
    Description = "Image size WIDTHxHEIGHT",
    HelpName = "WxH",
    DefaultValueFactory = _ => ImageSize.Default.ToString(),
  };

  readonly Option<int> spp = new("--spp")
  {
    Description = "Samples per pixel: 1 = pixel centre, N > 1 = jittered n×n grid (rounded up to a square)",
    DefaultValueFactory = _ => 1,
  };

  readonly Option<double> jitter = new("--jitter")
  {
    Description = "Jitter of supersamples within their cell, 0 to 1",
    DefaultValueFactory = _ => 1.0,
  };

  readonly Option<int> threads = new("--threads", "-t")
  {
    Description = "Worker threads; 0 = one per processor",
    DefaultValueFactory = _ => 0,
  };

  readonly Option<long> seed = new("--seed")
  {
    Description = "Seed of all sampling randomness (same seed ⇒ same image on any thread count)",
    DefaultValueFactory = _ => 0L,
  };

  readonly Option<string> sampler = CreateSamplerOption();

  static Option<string> CreateSamplerOption()
  {
    var o = new Option<string>("--sampler")
    {
      Description = "Sample generator of the random decisions (lens, area lights, glossy rays, path vertices): cmj = correlated multi-jitter; independent = uniform random; sobol = Owen-scrambled Sobol (best with a power-of-two --spp)",
      HelpName = "cmj|independent|sobol",
      DefaultValueFactory = _ => "cmj",
    };
    o.AcceptOnlyFromAmong("cmj", "independent", "sobol");
    return o;
  }

  readonly Option<double> gamma = new("--gamma")
  {
    Description = "Display gamma of the PNG (1 = linear)",
    DefaultValueFactory = _ => Rendering.Execution.RenderDefaults.Gamma,
  };

  readonly Option<bool> noShadows = new("--no-shadows") { Description = "Do not cast shadow rays" };
  readonly Option<bool> noReflections = new("--no-reflections") { Description = "Do not trace reflected rays" };
  readonly Option<bool> noRefractions = new("--no-refractions") { Description = "Do not trace refracted rays" };
  readonly Option<string> accel = AccelOption.Create();

  readonly Option<string> algorithm = CreateAlgorithmOption();

  static Option<string> CreateAlgorithmOption()
  {
    var o = new Option<string>("--algorithm", "-a")
    {
      Description = "Image function when the script chooses none (a given one replaces the script's): raytracing = Whitted (GrCis's default); distributed = glossy rays, soft shadows, depth of field (use --spp 16 or more); path = Monte Carlo path tracing",
      HelpName = "raytracing|distributed|path",
      DefaultValueFactory = _ => "raytracing",
    };
    o.AcceptOnlyFromAmong([.. RenderAlgorithmNames.All]);
    return o;
  }

  // The option accepts only known names, so anything else is its default.
  static RenderAlgorithm ParseAlgorithm(string? value) =>
    RenderAlgorithmNames.TryParse(value, out RenderAlgorithm a) ? a : RenderAlgorithm.RayTracing;

  public void AddTo(Command command)
  {
    foreach (Option o in new Option[] { size, spp, jitter, threads, seed, sampler, gamma, noShadows, noReflections, noRefractions, accel, algorithm })
      command.Options.Add(o);
  }

  /// <summary>Which options the user typed (they win over a scene script's context values).</summary>
  public GivenSettings Given(ParseResult parse) =>
    (IsGiven(parse, size) ? GivenSettings.Size : 0) |
    (IsGiven(parse, spp) ? GivenSettings.SamplesPerPixel : 0) |
    (IsGiven(parse, jitter) ? GivenSettings.Jitter : 0) |
    (IsGiven(parse, gamma) ? GivenSettings.Gamma : 0) |
    (IsGiven(parse, accel) ? GivenSettings.Accel : 0) |
    (IsGiven(parse, algorithm) ? GivenSettings.Algorithm : 0) |
    (parse.GetValue(noShadows) ? GivenSettings.Shadows : 0) |
    (parse.GetValue(noReflections) ? GivenSettings.Reflections : 0) |
    (parse.GetValue(noRefractions) ? GivenSettings.Refractions : 0);

  static bool IsGiven(ParseResult parse, Option option) => parse.GetResult(option) is { Implicit: false };

  /// <exception cref="UsageException">A value outside its allowed range.</exception>
  public RenderSettings Read(ParseResult parse)
  {
    ImageSize imageSize = ImageSize.Parse(parse.GetValue(size) ?? ImageSize.Default.ToString());
    return new RenderSettings
    {
    Width = imageSize.Width,
    Height = imageSize.Height,
    SamplesPerPixel = parse.GetValue(spp),
    Jitter = parse.GetValue(jitter),
    Threads = parse.GetValue(threads),
    Seed = parse.GetValue(seed),
    Sampler = Rendering.Sampler.TryParse(parse.GetValue(sampler), out Rendering.SamplerKind kind) ? kind : Rendering.SamplerKind.CorrelatedMultiJitter,
    Gamma = parse.GetValue(gamma),
    Shadows = !parse.GetValue(noShadows),
    Reflections = !parse.GetValue(noReflections),
    Refractions = !parse.GetValue(noRefractions),
    Accel = AccelOption.Parse(parse.GetValue(accel)),
    Algorithm = ParseAlgorithm(parse.GetValue(algorithm)),
    }.ValidateOptions();
  }
}
