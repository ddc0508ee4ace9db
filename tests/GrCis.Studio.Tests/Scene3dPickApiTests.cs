using System;
using System.Collections.Generic;
using System.Linq;
using System.Net;
using System.Net.Http;
using System.Net.Http.Json;
using System.Text.Json;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>
/// What the 3D view's hover, pick and points layer read: <c>GET /api/probe</c> naming the tessellation's part a pixel's
/// primary ray hit, and <c>GET /api/scene/points</c>, the render's primary-ray hits on a grid, lying on the solids' surfaces.
/// </summary>
public sealed class Scene3dPickApiTests(StudioFixture studio) : IClassFixture<StudioFixture>
{
  const int Width = 64, Height = 48;

  /// <summary>Two spheres rendered small; its tessellation's parts (Sphere 1, Sphere 2, Plane 3) and camera.</summary>
  async Task<JsonElement> RenderTwoSpheres()
  {
    await studio.RenderAndWait(new { scene = "Two spheres", settings = new { width = Width, height = Height } });
    return await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/tessellation");
  }

  /// <summary>Part <paramref name="i"/>'s centre and (uniform) scale: its matrix's last row and the length of its first.</summary>
  static (double[] Centre, double Radius) Ball(JsonElement scene, int i)
  {
    double[] m = scene.GetProperty("parts")[i].GetProperty("matrix").EnumerateArray().Select(e => e.GetDouble()).ToArray();
    return ([m[12], m[13], m[14]], Math.Sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]));
  }

  /// <summary>The pixel that sees world point <paramref name="p"/> through the tessellation's pinhole camera (GrCis's left-handed world: right = up × direction).</summary>
  static (int X, int Y) PixelOf(JsonElement scene, double[] p)
  {
    JsonElement c = scene.GetProperty("camera");
    double[] eye = Vec(c, "position"), dir = Vec(c, "direction"), up = Vec(c, "up");
    double[] right = [up[1] * dir[2] - up[2] * dir[1], up[2] * dir[0] - up[0] * dir[2], up[0] * dir[1] - up[1] * dir[0]];
    double[] d = [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]];
    double Dot(double[] a, double[] b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    double tanV = Math.Tan(c.GetProperty("verticalFov").GetDouble() / 2), z = Dot(d, dir);
    double x = Dot(d, right) / Math.Sqrt(Dot(right, right)) / (z * tanV * c.GetProperty("aspect").GetDouble());
    double y = Dot(d, up) / (z * tanV);
    return ((int)Math.Floor((1 + x) * Width / 2), (int)Math.Floor((1 - y) * Height / 2));
  }

  static double[] Vec(JsonElement e, string name) => e.GetProperty(name).EnumerateArray().Select(v => v.GetDouble()).ToArray();

  [Fact]
  public async Task A_probe_names_the_part_its_primary_ray_hit_and_none_for_the_background()
  {
    JsonElement scene = await RenderTwoSpheres();
    Assert.Equal(["Sphere 1", "Sphere 2", "Plane 3"], scene.GetProperty("parts").EnumerateArray().Select(p => p.GetProperty("name").GetString()));
    for (int i = 0; i < 2; i++)
    {
      (int x, int y) = PixelOf(scene, Ball(scene, i).Centre);
      JsonElement probe = await studio.Client.GetFromJsonAsync<JsonElement>($"/api/probe?x={x}&y={y}");
      Assert.Equal((i, $"Sphere {i + 1}"), (probe.GetProperty("part").GetInt32(), probe.GetProperty("partName").GetString()));
      Assert.Equal(i, probe.GetProperty("rays").GetProperty("part").GetInt32());
    }
    // The glass ball's refracted ray leaves it and its reflected ray meets the plane: each ray names its own part.
    JsonElement glass = await studio.Client.GetFromJsonAsync<JsonElement>($"/api/probe?x={PixelOf(scene, Ball(scene, 0).Centre).X}&y={PixelOf(scene, Ball(scene, 0).Centre).Y}");
    Assert.Contains(Flatten(glass.GetProperty("rays")), r => r.GetProperty("kind").GetString() != "Primary" && r.GetProperty("part").ValueKind == JsonValueKind.Number);
    // The top left corner looks above the horizon: the background, no part.
    JsonElement sky = await studio.Client.GetFromJsonAsync<JsonElement>("/api/probe?x=0&y=0");
    Assert.Equal(JsonValueKind.Null, sky.GetProperty("part").ValueKind);
    Assert.Equal(JsonValueKind.Null, sky.GetProperty("partName").ValueKind);
  }

  static IEnumerable<JsonElement> Flatten(JsonElement ray) =>
    new[] { ray }.Concat(ray.GetProperty("children").EnumerateArray().SelectMany(Flatten));

  [Fact]
  public async Task The_points_lie_on_the_surfaces_the_rays_hit_coloured_as_the_render()
  {
    JsonElement scene = await RenderTwoSpheres();
    JsonElement points = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/points?max=1000");

    int rays = points.GetProperty("rays").GetInt32(), count = points.GetProperty("count").GetInt32(), step = points.GetProperty("step").GetInt32();
    Assert.InRange(rays, 700, 1000);
    Assert.Equal((Width + step - 1 - step / 2) / step * ((Height + step - 1 - step / 2) / step), rays);
    // Most of the image is the plane and the balls; the sky above the horizon is not hit.
    Assert.InRange(count, rays / 2, rays - 1);
    float[] xyz = Floats(points, "positions"), rgb = Floats(points, "colors");
    int[] part = points.GetProperty("parts").EnumerateArray().Select(e => e.GetInt32()).ToArray();
    Assert.Equal((3 * count, 3 * count, count), (xyz.Length, rgb.Length, part.Length));
    Assert.Equal([0, 1, 2], part.Distinct().Order());

    double planeY = scene.GetProperty("parts")[2].GetProperty("matrix")[13].GetDouble();
    double[] yellow = new double[3];
    int onOpaque = 0;
    for (int i = 0; i < count; i++)
    {
      double[] p = [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];
      if (part[i] == 2)
      {
        Assert.Equal(planeY, p[1], 4);
        continue;
      }
      (double[] c, double r) = Ball(scene, part[i]);
      double distance = Math.Sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]));
      Assert.True(Math.Abs(distance - r) < 1e-4 * r, $"point {i} ({p[0]}, {p[1]}, {p[2]}) is {distance} from Sphere {part[i] + 1}'s centre, not {r}");
      if (part[i] == 1)
      {
        onOpaque++;
        for (int k = 0; k < 3; k++)
          yellow[k] += rgb[3 * i + k];
      }
    }
    // The opaque ball's material is (1, 0.8, 0.1): its pixels are far more red than blue.
    Assert.True(onOpaque > 20 && yellow[0] > 3 * yellow[2], $"{onOpaque} points on the opaque ball, colour sum ({string.Join(", ", yellow)})");

    // The same render gives the same points.
    JsonElement again = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/points?max=1000");
    Assert.Equal(xyz, Floats(again, "positions"));
    Assert.Equal(rgb, Floats(again, "colors"));
  }

  [Fact]
  public async Task A_csg_differences_points_lie_on_the_result_not_on_its_operands_whole()
  {
    // A ball bitten at its front by a smaller one: the camera looks into the bite.
    string path = System.IO.Path.Combine(studio.ScriptsFolder, "Bitten.cs");
    System.IO.File.WriteAllText(path, """
      CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
      root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
      root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
      scene.Intersectable = root;
      scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };
      scene.Camera = new StaticCamera(new Vector3d(0.0, 0.0, -6.0), new Vector3d(0.0, 0.0, 1.0), 40.0);
      scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
      scene.Sources.Add(new PointLightSource(new Vector3d(-2.0, 4.0, -5.0), 1.0));
      CSGInnerNode bitten = new CSGInnerNode(SetOperation.Difference);
      bitten.InsertChild(new Sphere(), Matrix4d.Identity);
      bitten.InsertChild(new Sphere(), Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(0.0, 0.0, -0.9));
      root.InsertChild(bitten, Matrix4d.Identity);
      """);
    string name;
    using (HttpResponseMessage added = await studio.Client.PostAsJsonAsync("/api/scenes/add", new { path }))
      name = (await added.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("name").GetString()!;
    await studio.RenderAndWait(new { scene = name, settings = new { width = 48, height = 48 } });
    JsonElement points = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/points");

    float[] xyz = Floats(points, "positions");
    int[] part = points.GetProperty("parts").EnumerateArray().Select(e => e.GetInt32()).ToArray();
    double Distance(int i, double cz) => Math.Sqrt(xyz[3 * i] * xyz[3 * i] + xyz[3 * i + 1] * xyz[3 * i + 1] + (xyz[3 * i + 2] - cz) * (xyz[3 * i + 2] - cz));
    int[] onBig = Enumerable.Range(0, part.Length).Where(i => part[i] == 0).ToArray(), inBite = Enumerable.Range(0, part.Length).Where(i => part[i] == 1).ToArray();
    Assert.True(onBig.Length > 50 && inBite.Length > 50, $"{onBig.Length} points on the ball, {inBite.Length} in the bite");
    // The ball's surface where the bite is not, and the bite's surface inside the ball: the difference, not its operands.
    Assert.All(onBig, i => Assert.True(Math.Abs(Distance(i, 0) - 1) < 1e-4 && Distance(i, -0.9) > 0.6 - 1e-4, $"point {i}"));
    Assert.All(inBite, i => Assert.True(Math.Abs(Distance(i, -0.9) - 0.6) < 1e-4 && Distance(i, 0) < 1 + 1e-4, $"point {i}"));
  }

  static float[] Floats(JsonElement e, string name) => e.GetProperty(name).EnumerateArray().Select(v => v.GetSingle()).ToArray();

  [Fact]
  public async Task Points_are_asked_for_within_bounds_and_behind_the_token()
  {
    await RenderTwoSpheres();
    using HttpResponseMessage none = await studio.Client.GetAsync("/api/scene/points?max=0");
    Assert.Equal(HttpStatusCode.BadRequest, none.StatusCode);
    using HttpResponseMessage many = await studio.Client.GetAsync("/api/scene/points?max=1000000");
    Assert.Equal(HttpStatusCode.BadRequest, many.StatusCode);
    Assert.Contains("250,000", await many.Content.ReadAsStringAsync());
    JsonElement all = await studio.Client.GetFromJsonAsync<JsonElement>("/api/scene/points");
    Assert.Equal((1, Width * Height), (all.GetProperty("step").GetInt32(), all.GetProperty("rays").GetInt32()));
    using HttpResponseMessage stranger = await studio.Stranger.GetAsync("/api/scene/points");
    Assert.Equal(HttpStatusCode.Unauthorized, stranger.StatusCode);
  }
}
