using Scene3D;
using System;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// A mesh hit asked for with <see cref="HitData.Surface"/> (<see cref="HitCompletion.OwnSurface"/>) carries the full hit's
/// surface to the bit: the point, the normal (face or interpolated, under a non-uniform scale), the texture coordinates
/// and the colour; a triangle too small for its normal gets the full completion.
/// </summary>
public class MeshSurfaceCompletionTests
{
  [Theory]
  [InlineData("smooth torus", true, false, 1.0)]
  [InlineData("flat torus", false, false, 1.0)]
  [InlineData("textured sheet", false, true, 1.0)]
  [InlineData("tiny textured sheet", true, true, 1e-7)]
  public void A_surface_only_mesh_hit_has_the_full_hits_surface(string kind, bool smooth, bool sheet, double size)
  {
    // size < 1: triangles so small that the world normal is within GrCis's zero length (the full completion's case),
    // scaled up again in the scene so that the rays are ordinary.
    SceneBrep brep = sheet ? TexturedSheet(12, size) : ProceduralMesh.Torus(24, 12);
    var mesh = new TriangleMesh(brep) { Smooth = smooth };
    mesh.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.2, 0.5, 1.0 }, 0.1, 0.7, 0.2, 32));
    if (sheet)
      mesh.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(4.0, 4.0, new[] { 1.0, 0.0, 0.0 }));
    var root = new CSGInnerNode(SetOperation.Union);
    // A non-uniform scale and a turn: the world normal goes through the inverse transpose.
    root.InsertChild(mesh, Matrix4d.Scale(1.0 / size, 0.5 / size, 2.0 / size) * Matrix4d.RotateX(-0.7) * Matrix4d.RotateY(0.3));
    PreparedScene scene = PreparedScene.Prepare(root);
    Assert.Equal(HitCompletion.OwnSurface, scene.Capabilities.Of(mesh)!.Value.Completion);

    var r = new Random(kind.Length);
    int compared = 0;
    for (int n = 0; n < 3000; n++)
    {
      // From a wide square in front towards a random point of the solid's region.
      var p0 = new Vector3d(r.NextDouble() * 6 - 3, r.NextDouble() * 6 - 3, -8);
      var p1 = new Vector3d(r.NextDouble() * 2 - 1, r.NextDouble() * 1.4 - 0.7, r.NextDouble() * 2 - 1) - p0;
      Intersection? full = scene.FirstHit(p0, p1, new Intersection(), HitData.All);
      Intersection? surface = scene.FirstHit(p0, p1, new Intersection(), HitData.Surface);
      Assert.Equal(full == null, surface == null);
      if (full == null || surface == null)
        continue;
      compared++;
      Assert.Equal(full.T, surface.T);
      Assert.Equal(full.CoordWorld, surface.CoordWorld);
      Assert.Equal(full.NormalLocal, surface.NormalLocal);
      Assert.Equal(full.Normal, surface.Normal);
      Assert.Equal(full.TextureCoord, surface.TextureCoord);
      Assert.Equal(full.SurfaceColor, surface.SurfaceColor);
      Assert.Equal(full.Enter, surface.Enter);
      // Tangents are what only the full completion computes: present in the tiny case (its fallback), absent otherwise.
      Assert.Equal(size < 1.0, surface.TangentU != Vector3d.Zero);
    }
    Assert.True(compared > 300, $"{compared} hits");
  }

  [Fact]
  public void A_student_mesh_that_overrides_the_completion_keeps_the_full_one()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var student = new StudentMesh(ProceduralMesh.Torus(12, 6));
    student.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.2, 0.5, 1.0 }, 0.1, 0.7, 0.2, 32));
    root.InsertChild(student, Matrix4d.Identity);
    PreparedScene scene = PreparedScene.Prepare(root);
    Assert.Equal(HitCompletion.Full, scene.Capabilities.Of(student)!.Value.Completion);
  }

  sealed class StudentMesh(SceneBrep m) : TriangleMesh(m)
  {
    public override void CompleteIntersection(Intersection inter)
    {
      base.CompleteIntersection(inter);
      inter.Normal = -inter.Normal;
    }
  }

  /// <summary>A wavy open sheet of the given size with texture coordinates and no vertex normals.</summary>
  static SceneBrep TexturedSheet(int n, double size)
  {
    var m = new SceneBrep();
    for (int i = 0; i <= n; i++)
      for (int j = 0; j <= n; j++)
      {
        double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
        int v = m.AddVertex((Vector3)(size * new Vector3d(x, y, 0.3 * Math.Sin(3 * x) * Math.Cos(2 * y))));
        m.SetTxtCoord(v, new Vector2((float)i / n, (float)j / n));
      }
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
      {
        int a = i * (n + 1) + j;
        m.AddTriangle(a, a + n + 1, a + n + 2);
        m.AddTriangle(a, a + n + 2, a + 1);
      }
    return m;
  }
}
