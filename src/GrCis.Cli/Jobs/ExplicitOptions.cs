namespace GrCis.Cli.Jobs;

/// <summary>
/// Which render options the user typed (as opposed to their defaults). An option given on the
/// command line wins over the scene script's context value, which wins over the default.
/// </summary>
public readonly record struct ExplicitOptions(
  bool Size = false,
  bool SamplesPerPixel = false,
  bool Jitter = false,
  bool Gamma = false,
  bool NoShadows = false,
  bool NoReflections = false,
  bool NoRefractions = false)
{
  /// <summary>A switch of the image function was given (<c>--no-shadows</c> and the like).</summary>
  public bool AnyImageFunctionSwitch => NoShadows || NoReflections || NoRefractions;

  /// <summary>A sampling option was given that the script's own renderer cannot honour.</summary>
  public bool AnySamplingOption => SamplesPerPixel || Jitter;
}
