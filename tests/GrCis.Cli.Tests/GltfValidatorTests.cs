using System;
using System.Collections.Generic;
using System.Formats.Tar;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Net.Http;
using System.Security.Cryptography;
using System.Text.Json;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// Every script of scripts/ exported by <c>grcis export</c> (as <c>.glb</c>, and one as <c>.gltf</c> with its
/// <c>.bin</c>) passes the Khronos glTF validator with no error. The validator is the npm package gltf-validator (the
/// validator compiled to JavaScript, no dependencies), fetched once from the npm registry at a pinned version and
/// checked against its published SHA-512, and run by Node.js (Debian package nodejs).
/// </summary>
public class GltfValidatorTests
{
  const string Version = "2.0.0-dev.3.10";

  // The registry's "dist.integrity" of that version.
  const string Integrity = "sha512-odJ4k0tRkGXiDGn78yDBg+fBbAIvBnXxh3RwAta0emSxGtyagFE8B4xELB1oYe3S5RD8Ci3uZAsZaascH2LAEQ==";

  [SkippableFact]
  public void Every_script_exports_a_file_the_Khronos_validator_finds_no_error_in()
  {
    string node = RequiredTool.Find("node", "nodejs");
    string validator = Validator();
    using var dir = new TempDirectory();
    List<string> files = ExportedScripts.Glb(dir);
    CliRun json = CliRun.Of(dir.Path, "export", RepoPaths.Script("TwoSpheres.cs"), "-o", "two-spheres.gltf", "-q");
    Assert.True(json.ExitCode == 0, json.Error);
    files.Add(dir.File("two-spheres.gltf"));

    JsonElement[] reports = ExportedScripts.Reports(node, [ExportedScripts.Data("validate-gltf.js"), validator], files);
    string[] failing = reports.Where(r => r.GetProperty("errors").GetInt32() > 0)
      .Select(r => $"{r.GetProperty("file").GetString()}: {string.Join("; ", r.GetProperty("messages").EnumerateArray().Select(m => m.GetString()))}")
      .ToArray();
    Assert.True(failing.Length == 0, "glTF validator errors:\n" + string.Join("\n", failing));
  }

  /// <summary>
  /// The folder of the validator package, fetched (once per machine, into the temporary folder) from the registry npm
  /// uses (<c>npm_config_registry</c>, else registry.npmjs.org) and checked against <see cref="Integrity"/>.
  /// </summary>
  static string Validator()
  {
    string folder = Path.Combine(Path.GetTempPath(), "grcis-tests", "gltf-validator-" + Version);
    if (File.Exists(Path.Combine(folder, "package", "index.js")))
      return Path.Combine(folder, "package");

    string registry = (Environment.GetEnvironmentVariable("npm_config_registry") ?? Environment.GetEnvironmentVariable("NPM_CONFIG_REGISTRY")
                       ?? "https://registry.npmjs.org/").TrimEnd('/');
    string url = $"{registry}/gltf-validator/-/gltf-validator-{Version}.tgz";
    byte[] tarball;
    try
    {
      using var http = new HttpClient { Timeout = TimeSpan.FromMinutes(2) };
      tarball = http.GetByteArrayAsync(url).GetAwaiter().GetResult();
    }
    catch (Exception e) when (e is HttpRequestException or System.Threading.Tasks.TaskCanceledException)
    {
      throw RequiredTool.Unavailable($"the npm package gltf-validator {Version} could not be fetched from {url}: {e.Message}");
    }
    string digest = "sha512-" + Convert.ToBase64String(SHA512.HashData(tarball));
    Assert.True(digest == Integrity, $"{url} is not the published package (its SHA-512 differs)");

    // Unpacked beside and renamed into place, so a run that stops half-way or a second run at the same time never
    // leaves or meets half a package.
    string unpacking = folder + "." + Guid.NewGuid().ToString("N");
    Directory.CreateDirectory(unpacking);
    using (var gzip = new GZipStream(new MemoryStream(tarball), CompressionMode.Decompress))
      TarFile.ExtractToDirectory(gzip, unpacking, overwriteFiles: false);
    try
    {
      Directory.Move(unpacking, folder);
    }
    catch (IOException) when (Directory.Exists(folder))
    {
      Directory.Delete(unpacking, recursive: true);
    }
    return Path.Combine(folder, "package");
  }
}
