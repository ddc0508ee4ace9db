using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Rendering.Imaging;

namespace Rendering.Parts;

/// <summary>
/// Assembles the parts of one still. Every pixel's value depends only on (seed, frame, pixel), so the
/// assembled image equals the one-process render bit for bit; the checks make sure the parts really
/// come from one render and cover every tile exactly once.
/// </summary>
public static class PartMerge
{
  /// <exception cref="PartMergeException">Parts missing, repeated, or from different renders.</exception>
  public static (FloatImage Image, PartHeader Header) Merge(IReadOnlyList<(string Path, PartHeader Header, float[] Samples)> parts)
  {
    ArgumentNullException.ThrowIfNull(parts);
    if (parts.Count == 0)
      throw new PartMergeException("no parts to merge");

    (string firstPath, PartHeader first, _) = parts[0];
    foreach ((string path, PartHeader h, _) in parts.Skip(1))
      if (h.Shared != first.Shared)
        throw new PartMergeException($"'{path}' is not from the same render as '{firstPath}': {Differences(first, h)} differ");

    var byIndex = new Dictionary<int, string>();
    foreach ((string path, PartHeader h, _) in parts)
      if (!byIndex.TryAdd(h.Index, path))
        throw new PartMergeException($"overlapping parts: '{byIndex[h.Index]}' and '{path}' are both part {h.Index}/{h.Count}");

    int[] missing = Enumerable.Range(0, first.Count).Where(i => !byIndex.ContainsKey(i)).ToArray();
    if (missing.Length > 0)
      throw new PartMergeException(string.Create(CultureInfo.InvariantCulture,
        $"incomplete: {missing.Length} of {first.Count} parts missing ({string.Join(", ", missing.Take(8).Select(i => $"{i}/{first.Count}"))}{(missing.Length > 8 ? ", …" : "")})"));

    var image = new FloatImage(first.Width, first.Height, first.Bands);
    foreach ((_, PartHeader h, float[] samples) in parts)
      PartFile.Place(h, samples, image);
    return (image, first);
  }

  static string Differences(PartHeader a, PartHeader b)
  {
    var names = new List<string>();
    if (a.Width != b.Width || a.Height != b.Height) names.Add($"size ({a.Width}x{a.Height} vs {b.Width}x{b.Height})");
    if (a.Count != b.Count) names.Add($"part count ({a.Count} vs {b.Count})");
    if (a.Scene != b.Scene) names.Add($"scene ({a.Scene} vs {b.Scene})");
    if (a.SamplesPerPixel != b.SamplesPerPixel) names.Add($"spp ({a.SamplesPerPixel} vs {b.SamplesPerPixel})");
    if (a.Seed != b.Seed) names.Add($"seed ({a.Seed} vs {b.Seed})");
    if (a.Gamma != b.Gamma) names.Add(string.Create(CultureInfo.InvariantCulture, $"gamma ({a.Gamma} vs {b.Gamma})"));
    if (a.Layout != b.Layout || a.Bands != b.Bands) names.Add("layout");
    if (names.Count == 0) names.Add("scene settings");   // only the hash: script text, parameters, switches, time
    return string.Join(", ", names);
  }
}
