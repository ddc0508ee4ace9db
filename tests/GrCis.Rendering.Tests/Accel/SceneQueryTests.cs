using System;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// The query interface between shading and geometry: GrCis's lists and the prepared scene answer the same
/// first hits and the same shadow any-hits, and a hit asked for with <see cref="HitData.Surface"/> carries the
/// same surface as a full one.
/// </summary>
public class SceneQueryTests
{
  [Theory]
  [InlineData("Five balls")]
  [InlineData("Toroids")]
  [InlineData("Circus")]
  [InlineData("Hedgehog in the cage")]
  public void Both_implementations_answer_the_same_first_hits_and_shadow_rays(string name)
  {
    IRayScene scene = global::Rendering.Scenes.Create(name);
    ISceneQuery lists = new SceneLists(scene.Intersectable);
    ISceneQuery prepared = PreparedScene.Prepare(scene.Intersectable);
    Assert.Same(scene.Intersectable, lists.Source);
    Assert.Same(scene.Intersectable, prepared.Source);

    var r = new Random(17);
    var light = new Vector3d(-10, 12, -8);
    ICamera camera = scene.Camera!;
    camera.Width = 64;
    camera.Height = 48;
    int hits = 0, blocked = 0;
    for (int n = 0; n < 3000; n++)
    {
      // Camera rays through random points of the image.
      Assert.True(camera.GetRay(r.NextDouble() * 64, r.NextDouble() * 48, out Vector3d p0, out Vector3d p1));
      Intersection? a = lists.FirstHit(p0, p1);
      Intersection? b = prepared.FirstHit(p0, p1);
      Assert.Equal(a == null, b == null);
      if (a == null || b == null)
        continue;
      hits++;
      a.Complete();
      b.Complete();
      Assert.Equal(a.T, b.T);
      Assert.Same(a.Solid, b.Solid);
      Assert.Equal(a.CoordWorld, b.CoordWorld);
      Assert.Equal(a.Normal, b.Normal);

      // A shadow ray from just off the surface towards the light.
      Vector3d from = a.CoordWorld, dir = light - from;
      bool ab = lists.AnyHit(from, dir);
      Assert.Equal(ab, prepared.AnyHit(from, dir));
      if (ab)
        blocked++;
    }
    Assert.True(hits > 300, $"{hits} hits");
    Assert.True(blocked > 0 && blocked < hits, $"{blocked} of {hits} shadow rays blocked");
  }

  [Fact]
  public void A_surface_only_hit_has_the_full_hits_surface()
  {
    IRayScene scene = global::Rendering.Scenes.Create("Sphere on the plane");
    ISceneQuery q = PreparedScene.Prepare(scene.Intersectable);
    var r = new Random(3);
    int compared = 0;
    for (int n = 0; n < 2000; n++)
    {
      var p0 = new Vector3d(r.NextDouble() * 2 - 1, r.NextDouble() * 2, -6);
      var p1 = new Vector3d(r.NextDouble() - 0.5, r.NextDouble() - 0.7, 1.0);
      Intersection? full = q.FirstHit(p0, p1, new Intersection(), HitData.All);
      Intersection? surface = q.FirstHit(p0, p1, new Intersection(), HitData.Surface);
      Assert.Equal(full == null, surface == null);
      if (full == null || surface == null)
        continue;
      compared++;
      Assert.Equal(full.T, surface.T);
      Assert.Equal(full.CoordWorld, surface.CoordWorld);
      Assert.Equal(full.Normal, surface.Normal);
      if (full.Textures is { Count: > 0 })   // texture coordinates are part of the surface where a texture reads them
        Assert.Equal(full.TextureCoord, surface.TextureCoord);
      Assert.Equal(full.SurfaceColor, surface.SurfaceColor);
    }
    Assert.True(compared > 500, $"{compared} hits");
  }
}
