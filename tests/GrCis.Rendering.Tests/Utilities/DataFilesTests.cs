using System;
using System.IO;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

/// <summary>
/// Data files named as students named them for Windows GrCis, found in a fork's folder tree: relative to the
/// project's bin/Debug, with backslashes, in another letter case.
/// </summary>
public sealed class DataFilesTests : IDisposable
{
  // A fork of GrCis as students keep it:
  //   data/rtscenes/Scene.cs, scene.yaml      scene scripts and their data
  //   data/Textures/Wood.PNG
  //   048rtmontecarlo-script/MyScene.cs        a script in the project folder
  //   048rtmontecarlo-script/Textures/Marble.jpg
  //   048rtmontecarlo-script/bin/Debug/        GrCis's working folder
  readonly string repo = Path.Combine(Path.GetTempPath(), $"grcis-fork-{Guid.NewGuid():N}");
  readonly string scenes, project;

  public DataFilesTests()
  {
    scenes = Path.Combine(repo, "data", "rtscenes");
    project = Path.Combine(repo, "048rtmontecarlo-script");
    Directory.CreateDirectory(scenes);
    Directory.CreateDirectory(Path.Combine(repo, "data", "Textures"));
    Directory.CreateDirectory(Path.Combine(project, "Textures"));
    Directory.CreateDirectory(Path.Combine(project, "bin", "Debug"));
    Touch(Path.Combine(scenes, "scene.yaml"));
    Touch(Path.Combine(repo, "data", "Textures", "Wood.PNG"));
    Touch(Path.Combine(project, "Textures", "Marble.jpg"));
  }

  public void Dispose() => Directory.Delete(repo, recursive: true);

  static void Touch(string path) => File.WriteAllText(path, path);

  static string ResolveFrom(string scriptDirectory, string path)
  {
    using (DataFiles.UseScriptDirectory(scriptDirectory))
      return DataFiles.Resolve(path);
  }

  static void AssertFound(string expected, string resolved) =>
    Assert.Equal(Path.GetFullPath(expected), Path.GetFullPath(resolved));

  [Theory]
  [InlineData(@"..\..\..\data\rtscenes\scene.yaml")]
  [InlineData("../../../data/rtscenes/scene.yaml")]
  [InlineData(@"..\..\..\..\data\rtscenes\scene.yaml")]   // one level too many: still the repository's data
  public void A_path_for_the_bin_Debug_folder_is_found_from_a_script_in_data_rtscenes(string written)
  {
    AssertFound(Path.Combine(scenes, "scene.yaml"), ResolveFrom(scenes, written));
  }

  [Theory]
  [InlineData(@"..\..\..\data\rtscenes\scene.yaml", "data/rtscenes/scene.yaml")]
  [InlineData(@"..\..\Textures\Marble.jpg", "048rtmontecarlo-script/Textures/Marble.jpg")]
  [InlineData(@"..\..\..\data\Textures\Wood.PNG", "data/Textures/Wood.PNG")]
  public void A_path_for_the_bin_Debug_folder_is_found_from_a_script_in_the_project_folder(string written, string expected)
  {
    AssertFound(Path.Combine(repo, expected), ResolveFrom(project, written));
  }

  [Fact]
  public void Files_found_while_a_read_log_is_in_use_are_logged_as_full_paths()
  {
    var log = new System.Collections.Generic.List<string>();
    using (DataFiles.LogReads(log))
    {
      ResolveFrom(project, @"..\..\Textures\Marble.jpg");
      ResolveFrom(project, "missing.txt");   // not found: nothing to watch
    }
    ResolveFrom(scenes, "scene.yaml");       // after the scope: not logged
    Assert.Equal([Path.Combine(project, "Textures", "Marble.jpg")], log);
  }

  [Fact]
  public void A_path_for_the_project_folder_is_found_from_a_script_in_data_rtscenes()
  {
    // GrCis ran data/rtscenes/*.cs from 048rtmontecarlo-script/bin/Debug: "..\..\Textures" is that project's.
    AssertFound(Path.Combine(project, "Textures", "Marble.jpg"), ResolveFrom(scenes, @"..\..\textures\marble.jpg"));
  }

  [Fact]
  public void Two_projects_with_the_file_are_not_guessed_between()
  {
    string other = Path.Combine(repo, "062animation-script", "Textures");
    Directory.CreateDirectory(other);
    Touch(Path.Combine(other, "Marble.jpg"));
    Assert.Equal(@"..\..\Textures\Marble.jpg", ResolveFrom(scenes, @"..\..\Textures\Marble.jpg"));
  }

  [Fact]
  public void The_path_as_GrCis_resolved_it_from_bin_Debug_is_found_from_the_working_folder_itself()
  {
    AssertFound(Path.Combine(scenes, "scene.yaml"), ResolveFrom(Path.Combine(project, "bin", "Debug"), @"..\..\..\data\rtscenes\scene.yaml"));
  }

  [Theory]
  [InlineData(@"..\..\..\DATA\textures\wood.png")]
  [InlineData("../../../data/TEXTURES/WOOD.png")]
  public void Folder_and_file_names_match_in_any_letter_case(string written)
  {
    AssertFound(Path.Combine(repo, "data", "Textures", "Wood.PNG"), ResolveFrom(project, written));
  }

  [Fact]
  public void A_name_in_another_case_is_found_beside_the_script()
  {
    AssertFound(Path.Combine(project, "Textures", "Marble.jpg"), ResolveFrom(project, @"textures\MARBLE.JPG"));
  }

  [Fact]
  public void A_path_that_exists_relative_to_the_script_wins_over_the_working_folder_reading()
  {
    // ../Textures/Wood.PNG from data/rtscenes is data/Textures/Wood.PNG; dropping ".." would give data/rtscenes/Textures.
    Directory.CreateDirectory(Path.Combine(scenes, "Textures"));
    Touch(Path.Combine(scenes, "Textures", "Wood.PNG"));
    AssertFound(Path.Combine(repo, "data", "Textures", "Wood.PNG"), ResolveFrom(scenes, @"..\Textures\Wood.PNG"));
  }

  [Fact]
  public void The_nearest_folder_above_the_script_wins()
  {
    Directory.CreateDirectory(Path.Combine(repo, "data", "rtscenes", "data", "rtscenes"));
    Touch(Path.Combine(repo, "data", "rtscenes", "data", "rtscenes", "scene.yaml"));
    AssertFound(Path.Combine(scenes, "data", "rtscenes", "scene.yaml"), ResolveFrom(scenes, @"..\..\..\data\rtscenes\scene.yaml"));
  }

  [Fact]
  public void Two_names_differing_only_in_case_are_not_guessed_between()
  {
    Touch(Path.Combine(scenes, "Scene.yaml"));
    if (File.ReadAllText(Path.Combine(scenes, "scene.yaml")) != Path.Combine(scenes, "scene.yaml"))
      return;   // a file system that ignores case has only one of them, and finds it itself
    Assert.Equal("SCENE.YAML", ResolveFrom(scenes, "SCENE.YAML"));
  }

  [Fact]
  public void The_search_upwards_is_bounded()
  {
    string deep = Path.Combine(scenes, "a", "b", "c", "d", "e");
    Directory.CreateDirectory(deep);
    // data/Textures/Wood.PNG is 7 folders above "e": beyond SearchLevels (4) + the one "..".
    Assert.Equal(@"..\data\Textures\Wood.PNG", ResolveFrom(deep, @"..\data\Textures\Wood.PNG"));
    // Three folders higher up in the written path widen the search by as many.
    AssertFound(Path.Combine(repo, "data", "Textures", "Wood.PNG"), ResolveFrom(deep, @"..\..\..\..\data\Textures\Wood.PNG"));
  }

  [Fact]
  public void A_missing_file_resolves_to_what_was_written()
  {
    Assert.Equal(@"..\..\..\data\rtscenes\none.yaml", ResolveFrom(scenes, @"..\..\..\data\rtscenes\none.yaml"));
  }

  [Fact]
  public void Util_ReadTextFile_finds_files_as_the_readers_do()
  {
    using (DataFiles.UseScriptDirectory(project))
    {
      Assert.True(Util.ReadTextFile(@"..\..\..\data\rtscenes\Scene.YAML", out string text));
      Assert.Equal(Path.Combine(scenes, "scene.yaml"), text);
    }
  }
}
