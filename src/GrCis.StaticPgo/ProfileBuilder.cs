using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection.Metadata;

namespace GrCis.StaticPgo;

/// <summary>
/// Joins text dumps of training runs into one profile of the given assemblies: each run weighs alike
/// (<see cref="AddRun"/>), the same method's counts add up across runs (<see cref="ProfiledMethod.Add"/>), each is
/// found in its assembly by name, IL size and parameter count, and methods of other assemblies (the framework's, which
/// has its own profile) are left out.
/// </summary>
internal sealed class ProfileBuilder
{
  readonly Dictionary<string, ProfiledMethod> methods = new(StringComparer.Ordinal);

  /// <summary>
  /// The weight of one training run: its block and edge counts (and its histograms' call counts) are scaled so that
  /// they add up to this, whatever the run's length. Runs then weigh alike where they share a method: a long path-traced
  /// render no longer decides the branches of the sample loop and the scene queries for the Whitted renders (it made
  /// Two spheres 13 % slower), while the shape of the counts within each run's own methods is kept.
  /// </summary>
  public const long RunWeight = 1L << 26;

  /// <summary>
  /// Adds a training run's dump at the weight of every other run (<see cref="RunWeight"/>). The builder takes the dump:
  /// its counts are scaled, and later runs' added, in place (a dump is read once, so nothing is copied).
  /// </summary>
  public void AddRun(IReadOnlyList<ProfiledMethod> dump)
  {
    long total = dump.SelectMany(m => m.Schema).Where(e => e.IsCount).Sum(e => e.Values.Sum());
    if (total > 0)
    {
      double scale = (double)RunWeight / total;
      foreach (SchemaEntry entry in dump.SelectMany(m => m.Schema))
        if (entry.IsCount || entry.IsHistogramCount)
          for (int i = 0; i < entry.Values.Length; i++)
            // A block the run reached stays reached (at least 1), however rarely.
            entry.Values[i] = entry.Values[i] > 0 ? Math.Max(1L, (long)Math.Round(entry.Values[i] * scale)) : entry.Values[i];
    }
    AddDump(dump);
  }

  /// <summary>Adds a dump's counts as they are (<see cref="ProfiledMethod.Add"/>); the builder takes the dump, as <see cref="AddRun"/> does.</summary>
  public void AddDump(IEnumerable<ProfiledMethod> dump)
  {
    foreach (ProfiledMethod method in dump)
      if (methods.TryGetValue(method.Key, out ProfiledMethod? seen)) seen.Add(method);
      else methods[method.Key] = method;
  }

  public int DumpedMethods => methods.Count;

  /// <summary>Writes the profile of <paramref name="assemblyPaths"/>' methods; returns how many it holds.</summary>
  public int Write(IEnumerable<string> assemblyPaths, Stream output, string name, TextWriter log)
  {
    var writer = new MibcWriter();
    var opened = new List<ProfiledAssembly>();
    try
    {
      var byName = new Dictionary<string, List<(ProfiledAssembly Assembly, MethodDefinitionHandle Handle, int IlSize)>>(StringComparer.Ordinal);
      foreach (string path in assemblyPaths)
      {
        var assembly = new ProfiledAssembly(path);
        opened.Add(assembly);
        foreach ((string methodName, MethodDefinitionHandle handle, int ilSize) in assembly.Methods())
        {
          if (!byName.TryGetValue(methodName, out var list)) byName[methodName] = list = [];
          list.Add((assembly, handle, ilSize));
        }
      }
      foreach (ProfiledMethod method in methods.Values.OrderBy(m => m.Key, StringComparer.Ordinal))
      {
        if (!byName.TryGetValue(method.Name, out var candidates)) continue;
        var match = candidates.Where(c => c.IlSize == method.IlSize).ToList();
        if (match.Count > 1) match = match.Where(c => c.Assembly.ParameterCount(c.Handle) == method.ParameterCount).ToList();
        if (match.Count != 1)
        {
          log.WriteLine($"left out {method.Name} {method.Signature}: {(match.Count == 0 ? "no method with its IL size" : "overloads of the same IL size")}");
          continue;
        }
        try { writer.Add(match[0].Assembly, match[0].Handle, method); }
        catch (NotSupportedException e) { log.WriteLine($"left out {method.Name}: its signature has {e.Message}"); }
      }
      writer.Write(output, name);
      return writer.MethodCount;
    }
    finally
    {
      foreach (ProfiledAssembly assembly in opened) assembly.Dispose();
    }
  }
}
