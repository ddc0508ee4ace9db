using System;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;
using YamlDotNet.RepresentationModel;

namespace GrCis.Cli.Tests;

/// <summary>
/// The Kubernetes recipe of docs/scale-out.md, checked without a cluster: the Job manifest parses as YAML and
/// its shard count, completions and parallelism agree; the pods' JSON overrides parse and mount the same claim.
/// </summary>
public class KubernetesRecipeTests
{
  static string Page => File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "scale-out.md"));

  [Fact]
  public void Job_manifest_is_an_indexed_job_whose_shard_count_is_its_completions()
  {
    Match block = Regex.Match(Page, "`render-job.yaml`:\n\n```yaml\n(.*?)```", RegexOptions.Singleline);
    Assert.True(block.Success, "docs/scale-out.md has no render-job.yaml block");
    var yaml = new YamlStream();
    yaml.Load(new StringReader(block.Groups[1].Value));
    var job = (YamlMappingNode)Assert.Single(yaml.Documents).RootNode;

    Assert.Equal("batch/v1", Scalar(job, "apiVersion"));
    Assert.Equal("Job", Scalar(job, "kind"));
    var spec = (YamlMappingNode)job["spec"];
    Assert.Equal("Indexed", Scalar(spec, "completionMode"));
    int completions = int.Parse(Scalar(spec, "completions"));
    Assert.Equal(completions, int.Parse(Scalar(spec, "parallelism")));

    var pod = (YamlMappingNode)((YamlMappingNode)spec["template"])["spec"];
    Assert.Equal("Never", Scalar(pod, "restartPolicy"));
    var container = (YamlMappingNode)((YamlSequenceNode)pod["containers"]).Single();
    string command = string.Join(' ', ((YamlSequenceNode)container["args"]).Select(a => ((YamlScalarNode)a).Value));
    Assert.Contains($"--shard \"$JOB_COMPLETION_INDEX/{completions}\"", command);
    Assert.Contains("--resume", command);
    string claim = Scalar((YamlMappingNode)((YamlMappingNode)((YamlSequenceNode)pod["volumes"]).Single())["persistentVolumeClaim"], "claimName");
    Assert.Equal("grcis-work", claim);
  }

  [Fact]
  public void Pod_overrides_are_json_that_mount_the_work_claim()
  {
    MatchCollection overrides = Regex.Matches(Page, @"--overrides='([^']*)'");
    Assert.Equal(2, overrides.Count);   // the copy pod and the video pod
    foreach (Match m in overrides)
    {
      using JsonDocument doc = JsonDocument.Parse(m.Groups[1].Value);
      JsonElement spec = doc.RootElement.GetProperty("spec");
      Assert.Equal("grcis-work", spec.GetProperty("volumes")[0].GetProperty("persistentVolumeClaim").GetProperty("claimName").GetString());
      Assert.Equal("/work", spec.GetProperty("containers")[0].GetProperty("volumeMounts")[0].GetProperty("mountPath").GetString());
    }
  }

  static string Scalar(YamlMappingNode map, string key) => ((YamlScalarNode)map[key]).Value!;
}
