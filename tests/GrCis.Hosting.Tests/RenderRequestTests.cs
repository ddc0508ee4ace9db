using System;
using System.IO;
using Rendering;
using Rendering.Imaging;

namespace GrCis.Hosting.Tests;

/// <summary>
/// A render request (scene source, settings, which were given, time) prepared the same way for every front end:
/// the scene built, the precedence rule applied, the time set; and the prepared render gives the demo's image.
/// </summary>
public sealed class RenderRequestTests : IDisposable
{
  readonly string dir = Directory.CreateTempSubdirectory("grcis-request-").FullName;

  public void Dispose() => Directory.Delete(dir, recursive: true);

  static readonly RenderSettings Small = new() { Width = 48, Height = 32, SamplesPerPixel = 4, Threads = 2 };

  ScriptSceneSource Script(string body)
  {
    string path = Path.Combine(dir, "Scene.cs");
    File.WriteAllText(path, body);
    return new ScriptSceneSource(path, "", Array.Empty<string>());
  }

  const string SizedScene = """
    Rendering.Scenes.FiveBalls(scene);
    context[PropertyName.CTX_WIDTH] = 40;
    context[PropertyName.CTX_HEIGHT] = 20;
    context[PropertyName.CTX_SUPERSAMPLING] = 9;
    """;

  [Fact]
  public void A_script_finds_the_requested_size_supersampling_and_animation_range_in_its_context_and_they_stay_the_requests()
  {
    using ScriptSceneSource source = Script("""
      Rendering.Scenes.FiveBalls(scene);
      context["seen"] = $"{context[PropertyName.CTX_SCENE_NAME]} {context[PropertyName.CTX_WIDTH]}x{context[PropertyName.CTX_HEIGHT]} " +
                        $"ss{context[PropertyName.CTX_SUPERSAMPLING]} {context[PropertyName.CTX_START_ANIM]}-{context[PropertyName.CTX_END_ANIM]}@{context[PropertyName.CTX_FPS]}";
      """);
    PreparedRender setup = new RenderRequest(source, Small) { Start = 1.0, End = 3.0, Fps = 8.0 }.Prepare();
    Assert.Equal("Scene.cs 48x32 ss4 1-3@8", setup.Script!.Context["seen"]);
    // Read, not chosen: the settings are the request's and the range is not the script's.
    Assert.Equal((48, 32, 4), (setup.Settings.Width, setup.Settings.Height, setup.Settings.SamplesPerPixel));
    Assert.Null(setup.Timing!.Start);
    Assert.Null(setup.Timing.Fps);

    PreparedRender defaults = new RenderRequest(source, Small).Prepare();
    Assert.Equal("Scene.cs 48x32 ss4 0-10@25", defaults.Script!.Context["seen"]);
  }

  [Fact]
  public void A_scripts_size_applies_unless_the_size_was_given()
  {
    using ScriptSceneSource source = Script(SizedScene);
    PreparedRender byScript = new RenderRequest(source, Small).Prepare();
    Assert.Equal((40, 20, 9), (byScript.Settings.Width, byScript.Settings.Height, byScript.Settings.SamplesPerPixel));
    Assert.NotNull(byScript.Script);

    PreparedRender given = new RenderRequest(source, Small, GivenSettings.Size).Prepare();
    Assert.Equal((48, 32, 9), (given.Settings.Width, given.Settings.Height, given.Settings.SamplesPerPixel));
    Assert.Equal((48, 32), (given.Render().Image.Width, given.Render().Image.Height));
  }

  [Fact]
  public void A_script_asking_for_an_impossible_size_is_refused_with_its_name()
  {
    using ScriptSceneSource source = Script("Rendering.Scenes.FiveBalls(scene);\ncontext[PropertyName.CTX_WIDTH] = -5;\n");
    var e = Assert.Throws<ScriptChoiceException>(() => new RenderRequest(source, Small).Prepare());
    Assert.Contains("Scene.cs", e.Message);
  }

  [Fact]
  public void A_time_for_a_still_scene_is_ignored_with_a_note_in_the_front_ends_words()
  {
    var source = new BuiltInSceneSource("Sphere on the plane");
    PreparedRender plain = new RenderRequest(source, Small, Time: 2.0).Prepare(s => s == Setting.Time ? "--time" : s.ToString());
    Assert.Null(plain.Time);
    Assert.Contains(plain.Notes, n => n.Contains("--time is ignored", StringComparison.Ordinal));
    Assert.Empty(new RenderRequest(source, Small).Prepare().Notes);
  }

  [Fact]
  public void A_moving_scene_is_set_to_the_requested_time_and_clamped_to_its_range()
  {
    using ScriptSceneSource source = Script("""
      Rendering.Scenes.FiveBalls(scene);
      context[PropertyName.CTX_START_ANIM] = 0.0;
      context[PropertyName.CTX_END_ANIM] = 4.0;
      if (scene is ITimeDependent animated)
      {
        animated.Start = 0.0;
        animated.End = 4.0;
      }
      scene.Animator = new PropertyAnimator { Start = 0.0, End = 4.0 };
      """);
    PreparedRender at = new RenderRequest(source, Small, Time: 1.5).Prepare();
    Assert.Equal(1.5, at.Time);
    Assert.Equal(4.0, at.Timing!.End);

    PreparedRender outside = new RenderRequest(source, Small, Time: 9.0).Prepare();
    Assert.Equal(4.0, outside.Time);
    Assert.Contains(outside.Notes, n => n.Contains("outside the animation", StringComparison.Ordinal));
  }

  [Fact]
  public void The_prepared_render_and_the_demo_session_give_the_same_bytes()
  {
    PreparedRender request = new RenderRequest(new BuiltInSceneSource("Two spheres"), Small).Prepare();
    FloatImage fromRequest = request.Render().Image;

    using var session = new RenderSession(RenderJob.Create(Scenes.Create("Two spheres", ""), Small)) { CoarseBlock = 4 };
    FloatImage fromSession = session.Start().GetAwaiter().GetResult().Image;

    Assert.Equal(fromRequest.Data, fromSession.Data);
  }
}
