using GrCis.Hosting;

namespace GrCis.Cli.Jobs;

/// <summary>How <c>grcis</c> shows the shared <see cref="RenderSettings"/>: the size as <c>WxH</c>, a bad value as a usage error naming its option.</summary>
public static class CliSettings
{
  extension(RenderSettings settings)
  {
    /// <summary>The image size as the command line writes it.</summary>
    public ImageSize Size => new(settings.Width, settings.Height);

    /// <summary><see cref="RenderSettings.Validate"/>, with a value out of range reported as <c>invalid --option value: rule</c>.</summary>
    /// <exception cref="UsageException">A value outside its allowed range.</exception>
    public RenderSettings ValidateOptions()
    {
      try
      {
        return settings.Validate();
      }
      catch (InvalidSettingException e)
      {
        throw new UsageException($"invalid {OptionName(e.Setting)} {e.Value}: {e.Rule}");
      }
    }
  }

  /// <summary>The option that sets <paramref name="setting"/>.</summary>
  public static string OptionName(Setting setting) => setting switch
  {
    Setting.Size => "--size",
    Setting.SamplesPerPixel => "--spp",
    Setting.Jitter => "--jitter",
    Setting.Shadows => "--no-shadows",
    Setting.Reflections => "--no-reflections",
    Setting.Refractions => "--no-refractions",
    Setting.Accel => "--accel",
    Setting.Gamma => "--gamma",
    Setting.Threads => "--threads",
    Setting.Time => "--time",
    Setting.Algorithm => "--algorithm",
    _ => setting.ToString(),
  };
}
