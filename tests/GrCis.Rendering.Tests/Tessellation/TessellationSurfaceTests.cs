using System;
using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Tessellation;

namespace GrCis.Rendering.Tests.Tessellation;

/// <summary>
/// <see cref="SceneTessellator"/>: each library solid's triangles lie on its analytic surface once their world positions
/// are taken back into the node's object space by the scene graph's own <see cref="ISceneNode.ToWorld"/>; CSG leaves
/// carry their operation, colours are inherited as hits resolve them, a script's solid is its box.
/// </summary>
public class TessellationSurfaceTests
{
  /// <summary>A scene of transformed solids under nested unions: a rotated, scaled and moved copy of each.</summary>
  internal static (IRayScene Scene, Sphere Sphere, Cube Cube, Cylinder Cylinder, Torus Torus) Solids()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var group = new CSGInnerNode(SetOperation.Union);
    root.InsertChild(group, Matrix4d.CreateRotationY(0.4) * Matrix4d.CreateTranslation(1.0, 0.5, 2.0));
    var sphere = new Sphere();
    group.InsertChild(sphere, Matrix4d.Scale(0.7) * Matrix4d.CreateTranslation(-1.0, 0.0, 0.0));
    var cube = new Cube();
    group.InsertChild(cube, Matrix4d.Scale(1.5, 0.5, 0.8) * Matrix4d.CreateRotationZ(0.3));
    var cylinder = new Cylinder(-0.5, 1.5);
    root.InsertChild(cylinder, Matrix4d.CreateRotationX(-0.5 * Math.PI) * Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
    var torus = new Torus(1.0, 0.3);
    root.InsertChild(torus, Matrix4d.CreateRotationX(0.7) * Matrix4d.CreateTranslation(0.0, 2.0, 4.0));
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      Camera = new StaticCamera(new Vector3d(0.0, 1.0, -8.0), new Vector3d(0.0, -0.1, 1.0), 50.0),
      Sources = new List<ILightSource> { new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.0) },
    };
    return (scene, sphere, cube, cylinder, torus);
  }

  static TessellatedPart PartOf(SceneTessellation t, ISceneNode node) => t.Parts.Single(p => ReferenceEquals(p.Node, node));

  /// <summary>World vertex i taken back into the node's own space by the scene graph's inverse world matrix.</summary>
  static Vector3d ObjectSpace(TessellatedPart part, int i) => Vector3d.TransformPosition(part.WorldPosition(i), part.Node.ToWorld().Inverted());

  static IEnumerable<(Vector3d A, Vector3d B, Vector3d C)> Triangles(TessellatedPart part)
  {
    for (int t = 0; t < part.Indices.Length; t += 3)
      yield return (ObjectSpace(part, part.Indices[t]), ObjectSpace(part, part.Indices[t + 1]), ObjectSpace(part, part.Indices[t + 2]));
  }

  [Fact]
  public void Sphere_vertices_lie_on_the_unit_sphere_and_triangles_face_outwards_within_the_tolerance()
  {
    var (scene, sphere, _, _, _) = Solids();
    TessellatedPart part = PartOf(SceneTessellator.Tessellate(scene), sphere);

    Assert.Equal(PartKind.Surface, part.Kind);
    Assert.InRange(part.Tolerance, 1e-4, 0.02);
    for (int i = 0; i < part.Positions.Length; i++)
      Assert.Equal(1.0, ObjectSpace(part, i).Length, 9);
    foreach (var (a, b, c) in Triangles(part))
    {
      Vector3d centroid = (a + b + c) / 3.0;
      Assert.InRange(centroid.Length, 1.0 - part.Tolerance, 1.0);
      Assert.True(Vector3d.Dot(Vector3d.Cross(b - a, c - a), centroid) > 0.0, "a sphere triangle faces inwards");
    }
    // 48 segments × 24 rings, less the degenerate halves of the pole cells.
    Assert.Equal(2 * 48 * 24 - 2 * 48, part.TriangleCount);
  }

  [Fact]
  public void Cube_triangles_lie_on_the_faces_of_the_unit_cube_and_cover_each_face_twice()
  {
    var (scene, _, cube, _, _) = Solids();
    TessellatedPart part = PartOf(SceneTessellator.Tessellate(scene), cube);

    Assert.Equal(12, part.TriangleCount);
    var faces = new Dictionary<(int Axis, double Side), int>();
    foreach (var (a, b, c) in Triangles(part))
    {
      // One coordinate is 0 or 1 at all three corners: the triangle lies in that face.
      (int Axis, double Side)? face = null;
      for (int axis = 0; axis < 3 && face == null; axis++)
        foreach (double side in new[] { 0.0, 1.0 })
          if (Math.Abs(a[axis] - side) < 1e-9 && Math.Abs(b[axis] - side) < 1e-9 && Math.Abs(c[axis] - side) < 1e-9)
            face = (axis, side);
      Assert.NotNull(face);
      faces[face.Value] = faces.GetValueOrDefault(face.Value) + 1;
      Vector3d outward = Vector3d.Zero;
      outward[face.Value.Axis] = face.Value.Side == 0.0 ? -1.0 : 1.0;
      Assert.True(Vector3d.Dot(Vector3d.Cross(b - a, c - a), outward) > 0.0, "a cube triangle faces inwards");
    }
    Assert.Equal(6, faces.Count);
    Assert.All(faces.Values, n => Assert.Equal(2, n));
  }

  [Fact]
  public void Cylinder_vertices_lie_on_its_side_or_its_caps()
  {
    var (scene, _, _, cylinder, _) = Solids();
    TessellatedPart part = PartOf(SceneTessellator.Tessellate(scene), cylinder);

    for (int i = 0; i < part.Positions.Length; i++)
    {
      Vector3d p = ObjectSpace(part, i);
      double r = Math.Sqrt(p.X * p.X + p.Y * p.Y);
      bool onCap = Math.Abs(p.Z - cylinder.ZMin) < 1e-9 || Math.Abs(p.Z - cylinder.ZMax) < 1e-9;
      Assert.True(onCap ? r <= 1.0 + 1e-9 : Math.Abs(r - 1.0) < 1e-9, $"vertex {p} is off the cylinder");
      Assert.InRange(p.Z, cylinder.ZMin - 1e-9, cylinder.ZMax + 1e-9);
    }
    foreach (var (a, b, c) in Triangles(part))
    {
      Vector3d centroid = (a + b + c) / 3.0;
      Vector3d outward = Math.Abs(a.Z - b.Z) < 1e-12 && Math.Abs(b.Z - c.Z) < 1e-12
        ? new Vector3d(0.0, 0.0, a.Z - 0.5 * (cylinder.ZMin + cylinder.ZMax))
        : new Vector3d(centroid.X, centroid.Y, 0.0);
      Assert.True(Vector3d.Dot(Vector3d.Cross(b - a, c - a), outward) > 0.0, "a cylinder triangle faces inwards");
    }
  }

  [Fact]
  public void Torus_vertices_lie_on_the_torus()
  {
    var (scene, _, _, _, torus) = Solids();
    TessellatedPart part = PartOf(SceneTessellator.Tessellate(scene), torus);

    for (int i = 0; i < part.Positions.Length; i++)
    {
      Vector3d p = ObjectSpace(part, i);
      double ring = Math.Sqrt(p.X * p.X + p.Y * p.Y) - torus.bigRadius;
      Assert.Equal(torus.smallRadius, Math.Sqrt(ring * ring + p.Z * p.Z), 9);
    }
  }

  [Fact]
  public void The_camera_is_the_scenes_camera_at_the_options_image_size()
  {
    var (scene, _, _, _, _) = Solids();
    TessellatedCamera camera = SceneTessellator.Tessellate(scene, new TessellationOptions { Width = 400, Height = 200 }).Camera!;

    scene.Camera!.GetRay(200.0, 100.0, out Vector3d p0, out Vector3d dir);
    Assert.True((camera.Position - p0).Length < 1e-12);
    Assert.True((camera.Direction - dir).Length < 1e-12);
    Assert.Equal(2.0, camera.AspectRatio, 12);
    // The ray through the top edge's middle is half the vertical field of view away from the centre ray.
    scene.Camera.GetRay(200.0, 0.0, out _, out Vector3d top);
    Assert.Equal(0.5 * camera.VerticalFov, Vector3d.CalculateAngle(top, dir), 9);
    Assert.True(Vector3d.Dot(top - dir, camera.Up) > 0.0, "up points to the image's top");
    Assert.True(Math.Abs(Vector3d.Dot(camera.Up, camera.Direction)) < 1e-12);
  }

  [Fact]
  public void Csg_leaves_carry_the_operation_they_are_operands_of_and_colours_are_inherited()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var difference = new CSGInnerNode(SetOperation.Difference);
    difference.SetAttribute(PropertyName.COLOR, new[] { 0.1, 0.2, 0.3 });
    root.InsertChild(difference, Matrix4d.Identity);
    var outer = new Sphere();
    difference.InsertChild(outer, Matrix4d.Identity);
    var inner = new CSGInnerNode(SetOperation.Union);
    difference.InsertChild(inner, Matrix4d.Identity);
    var hole = new Cube();
    inner.InsertChild(hole, Matrix4d.CreateTranslation(-0.5, -0.5, -2.0));
    var plain = new Sphere();
    plain.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.9, 0.8, 0.7 }, 0.1, 0.8, 0.1, 10));
    root.InsertChild(plain, Matrix4d.CreateTranslation(3.0, 0.0, 0.0));

    SceneTessellation t = SceneTessellator.Tessellate(new DefaultRayScene { Intersectable = root });

    Assert.Equal(SetOperation.Difference, PartOf(t, outer).CsgOperation);
    Assert.Equal(SetOperation.Difference, PartOf(t, hole).CsgOperation);
    Assert.Null(PartOf(t, plain).CsgOperation);
    Assert.Equal(new Vector3d(0.1, 0.2, 0.3), PartOf(t, hole).BaseColor);
    Assert.Equal(new Vector3d(0.9, 0.8, 0.7), PartOf(t, plain).BaseColor);
    Assert.Equal(3, t.Parts.Count);
    Assert.Equal(new[] { "Sphere 1", "Cube 2", "Sphere 3" }, t.Parts.Select(p => p.Name));
  }

  /// <summary>A solid the library does not know (as a script would declare it).</summary>
  sealed class Blob : DefaultSceneNode, ISolid
  {
    public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
    {
      corner1 = new Vector3d(-1.0, -2.0, -3.0);
      corner2 = new Vector3d(1.0, 2.0, 3.0);
    }
  }

  [Fact]
  public void A_solid_of_a_class_the_library_does_not_know_is_its_bounding_box_and_a_note_says_so()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var blob = new Blob();
    root.InsertChild(blob, Matrix4d.CreateTranslation(5.0, 0.0, 0.0));
    root.InsertChild(new Sphere(), Matrix4d.Identity);

    SceneTessellation t = SceneTessellator.Tessellate(new DefaultRayScene { Intersectable = root });
    TessellatedPart part = PartOf(t, blob);

    Assert.Equal(PartKind.BoundingBox, part.Kind);
    Assert.Equal("Blob", part.TypeName);
    Assert.Equal(12, part.TriangleCount);
    Assert.Equal(new Vector3d(4.0, -2.0, -3.0), Enumerable.Range(0, 8).Select(part.WorldPosition).Aggregate(Vector3d.ComponentMin));
    Assert.Equal(new Vector3d(6.0, 2.0, 3.0), Enumerable.Range(0, 8).Select(part.WorldPosition).Aggregate(Vector3d.ComponentMax));
    Assert.Contains(t.Notes, n => n.Contains("Blob", StringComparison.Ordinal) && n.Contains("bounding box", StringComparison.Ordinal));
  }

  [Fact]
  public void An_infinite_plane_is_a_patch_covering_the_scenes_solids_and_camera()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var plane = new Plane();
    root.InsertChild(plane, Matrix4d.CreateRotationX(-0.5 * Math.PI));
    root.InsertChild(new Sphere(), Matrix4d.CreateTranslation(7.0, 1.0, 3.0));
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      Camera = new StaticCamera(new Vector3d(0.0, 2.0, -9.0), new Vector3d(0.0, -0.2, 1.0), 40.0),
    };

    TessellatedPart part = PartOf(SceneTessellator.Tessellate(scene), plane);
    var world = Enumerable.Range(0, part.Positions.Length).Select(part.WorldPosition).ToArray();
    Vector3d min = world.Aggregate(Vector3d.ComponentMin), max = world.Aggregate(Vector3d.ComponentMax);

    // The plane z = 0 turned to y = 0: the patch spans the sphere (x up to 8, z up to 4) and the camera (z = −9).
    Assert.All(world, p => Assert.Equal(0.0, p.Y, 9));
    Assert.True(min.X < -1.0 && max.X > 8.0 && min.Z < -9.0 && max.Z > 4.0, $"patch {min} .. {max}");
    Assert.NotNull(part.Note);
  }

  [Fact]
  public void Equal_shapes_share_their_arrays_and_lights_keep_their_places()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var a = new Sphere();
    var b = new Sphere();
    root.InsertChild(a, Matrix4d.Identity);
    root.InsertChild(b, Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
    var scene = new DefaultRayScene
    {
      Intersectable = root,
      Sources = new List<ILightSource>
      {
        new AmbientLightSource(0.1),
        new PointLightSource(new Vector3d(1.0, 2.0, 3.0), new[] { 0.5, 0.6, 0.7 }),
        new RectangleLightSource(new Vector3d(0.0, 4.0, 0.0), new Vector3d(2.0, 0.0, 0.0), new Vector3d(0.0, 0.0, 1.0), 1.0),
      },
    };

    SceneTessellation t = SceneTessellator.Tessellate(scene);

    Assert.Same(PartOf(t, a).Positions, PartOf(t, b).Positions);
    Assert.Equal(2, t.Lights.Count);
    Assert.Equal(TessellatedLightKind.Point, t.Lights[0].Kind);
    Assert.Equal(new Vector3d(0.5, 0.6, 0.7), t.Lights[0].Intensity);
    Assert.Equal(TessellatedLightKind.Rectangle, t.Lights[1].Kind);
    Assert.Equal(new Vector3d(1.0, 4.0, 0.5), t.Lights[1].Position);
  }
}
