using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using GrCis.Cli.Animation;
using GrCis.Cli.SceneSources;
using Rendering;
using Rendering.Parts;
using GrCis.Hosting;

namespace GrCis.Cli.Jobs;

/// <summary>
/// <c>render --tiles i/n</c>: the header of the part file, whose settings hash covers everything that
/// shapes the pixels (scene or script text and its modules' sources, --param, --time, size, sampling,
/// seed, sampler, gamma, switches, the script's renderer) and nothing that does not (threads, --accel).
/// </summary>
public static class StillPart
{
  public static PartHeader Header(ISceneSource source, PreparedRender setup, ShardSpec part, IEnumerable<string> modules, int samplesPerPixel)
  {
    RenderSettings s = setup.Settings;
    var id = new StringBuilder();
    id.Append(CultureInfo.InvariantCulture, $"scene {source.DisplayName}\n");
    if (source is ScriptSceneSource script)
    {
      id.Append(CultureInfo.InvariantCulture, $"script {Hash(File.ReadAllBytes(script.Path))}\nparam {script.Param}\n");
      foreach (string dir in modules)
        foreach (string file in Directory.GetFiles(dir, "*.cs", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
          id.Append(CultureInfo.InvariantCulture, $"module {Path.GetRelativePath(dir, file)} {Hash(File.ReadAllBytes(file))}\n");
    }
    id.Append(CultureInfo.InvariantCulture, $"""
      time {setup.Time:R}
      size {s.Size}
      spp {samplesPerPixel}
      jitter {s.Jitter:R}
      seed {s.Seed}
      gamma {s.Gamma:R}
      switches {s.Shadows} {s.Reflections} {s.Refractions}
      algorithm {s.Algorithm}
      renderer {setup.Synthesizer?.GetType().FullName ?? "default"}
      function {setup.ImageFunction?.GetType().FullName ?? "default"}
      """);
    // Named only when not the default, so parts rendered before samplers could be chosen still match.
    if (s.Sampler != SamplerKind.CorrelatedMultiJitter)
      id.Append(CultureInfo.InvariantCulture, $"\nsampler {Sampler.NameOf(s.Sampler)}");
    return new PartHeader
    {
      Width = s.Size.Width,
      Height = s.Size.Height,
      Index = part.Index,
      Count = part.Count,
      SamplesPerPixel = samplesPerPixel,
      Seed = s.Seed,
      Gamma = s.Gamma,
      Scene = source.DisplayName,
      SettingsHash = Hash(Encoding.UTF8.GetBytes(id.ToString())),
    };
  }

  static string Hash(byte[] data) => Convert.ToHexStringLower(SHA256.HashData(data));
}
