using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using GrCis.Hosting;
using Rendering;

namespace GrCis.Cli.Jobs;

/// <summary>
/// What makes a render's pixels, as text: the scene (a script by its content and its modules' sources, so
/// the same script at another path or on another machine matches, and its --param), the time, size,
/// sampling, seed, sampler, gamma, switches and the script's own renderer; nothing that leaves the pixels
/// alone (threads, --accel, --parallel, the shard). Part files (<see cref="StillPart"/>) and animation
/// frames (<see cref="Animation.FrameFingerprint"/>) carry its hash, so work of another render is recognised.
/// </summary>
public static class RenderIdentity
{
  /// <param name="source">The scene.</param>
  /// <param name="setup">The prepared scene and the settings after precedence.</param>
  /// <param name="modules">The module folders (<c>--module</c>), full paths.</param>
  /// <param name="samplesPerPixel">The samples per pixel taken.</param>
  /// <param name="time">The time line's value: a still's scene time, or what an animation's frames share.</param>
  public static string Describe(ISceneSource source, PreparedRender setup, IEnumerable<string> modules, int samplesPerPixel, string time)
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
    else if (source is BuiltInSceneSource { Param.Length: > 0 } builtIn)
    {
      // Only when given, so the text of a built-in scene without a parameter is what it always was.
      id.Append(CultureInfo.InvariantCulture, $"param {builtIn.Param}\n");
    }
    id.Append(CultureInfo.InvariantCulture, $"""
      time {time}
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
    return id.ToString();
  }

  /// <summary>Lower-case hex SHA-256 of <paramref name="text"/>'s UTF-8 bytes.</summary>
  public static string Hash(string text) => Hash(Encoding.UTF8.GetBytes(text));

  /// <summary>Lower-case hex SHA-256 of <paramref name="data"/>.</summary>
  public static string Hash(ReadOnlySpan<byte> data) => Convert.ToHexStringLower(SHA256.HashData(data));
}
