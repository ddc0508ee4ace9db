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
/// shapes the pixels and nothing that does not (<see cref="RenderIdentity"/>).
/// </summary>
public static class StillPart
{
  public static PartHeader Header(ISceneSource source, PreparedRender setup, ShardSpec part, IEnumerable<string> modules, int samplesPerPixel)
  {
    RenderSettings s = setup.Settings;
    string id = RenderIdentity.Describe(source, setup, modules, samplesPerPixel, string.Create(CultureInfo.InvariantCulture, $"{setup.Time:R}"));
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
      SettingsHash = RenderIdentity.Hash(id),
    };
  }
}
