using Scene3D;
using System;
using System.Collections.Generic;
using GrCis.Testing;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;
using Rendering.Imaging;

namespace GrCis.Rendering.Tests.Meshes;

/// <summary>A mesh without faces (an empty OBJ, an OBJ of only vertices) is a solid that is never hit.</summary>
public class EmptyMeshTests
{
  static DefaultRayScene Scene(ISolid? mesh, Matrix4d where)
  {
    var root = new CSGInnerNode(SetOperation.Union);
    root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
    root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
    var ball = new Sphere();
    ball.SetAttribute(PropertyName.COLOR, new[] { 1.0, 0.6, 0.1 });
    root.InsertChild(ball, Matrix4d.CreateTranslation(1.0, 0.0, 0.0));
    if (mesh != null)
      root.InsertChild(mesh, where);
    return new DefaultRayScene
    {
      Intersectable = root,
      BackgroundColor = new[] { 0.0, 0.05, 0.07 },
      Camera = new StaticCamera(new Vector3d(0, 0, -5), new Vector3d(0, 0, 1), 50),
      Sources = new LinkedList<ILightSource>(new ILightSource[] { new AmbientLightSource(0.6), new PointLightSource(new Vector3d(-4, 5, -4), 1.0) }),
    };
  }

  public static TheoryData<string, AccelMode> Meshes()
  {
    var data = new TheoryData<string, AccelMode>();
    foreach (string obj in new[] { "", "# nothing\n\ng empty\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" })
      foreach (AccelMode mode in new[] { AccelMode.None, AccelMode.Bvh })
        data.Add(obj, mode);
    return data;
  }

  [Theory]
  [MemberData(nameof(Meshes))]
  public void A_mesh_without_faces_renders_as_nothing(string obj, AccelMode mode)
  {
    SceneBrep brep = MeshTestSupport.Read(obj);
    Assert.Equal(0, brep.Triangles);
    Matrix4d where = Matrix4d.Scale(2.0) * Matrix4d.CreateTranslation(-1.0, 0.0, 0.0);

    FloatImage without = RenderHelper.Render(Scene(null, where), mode, 40, 30, threads: 2);
    FloatImage with = RenderHelper.Render(Scene(new TriangleMesh(brep), where), mode, 40, 30, threads: 2);
    Assert.Equal(without.Data, with.Data);
  }

  [Fact]
  public void A_mesh_without_faces_is_never_hit_and_as_a_CSG_operand_removes_nothing()
  {
    var empty = new TriangleMesh(new SceneBrep());
    Assert.Null(empty.Intersect(new Vector3d(0, 0, -5), Vector3d.UnitZ));

    var difference = new CSGInnerNode(SetOperation.Difference);
    difference.InsertChild(new Sphere(), Matrix4d.Identity);
    difference.InsertChild(empty, Matrix4d.Identity);
    LinkedList<Intersection>? hits = difference.Intersect(new Vector3d(0, 0, -5), Vector3d.UnitZ);
    Assert.NotNull(hits);
    Assert.Equal(4.0, hits!.First!.Value.T, 12);
  }
}
