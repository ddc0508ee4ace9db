using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.SceneGraph;

public class SceneNodeTests
{
  [Fact]
  public void Attributes_are_inherited_from_parents_and_overridden_locally()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var child = new IntervalSolid(0, 1);
    root.InsertChild(child, Matrix4d.Identity);
    double[] red = { 1, 0, 0 }, blue = { 0, 0, 1 };
    root.SetAttribute(PropertyName.COLOR, red);
    Assert.Same(red, child.GetAttribute(PropertyName.COLOR));
    Assert.Null(child.GetLocalAttribute(PropertyName.COLOR));
    child.SetAttribute(PropertyName.COLOR, blue);
    Assert.Same(blue, child.GetAttribute(PropertyName.COLOR));
  }

  [Fact]
  public void World_matrix_composes_child_then_parent_and_ignores_the_root_transform()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var mid = new CSGInnerNode(SetOperation.Union);
    var leaf = new IntervalSolid(0, 1);
    root.InsertChild(mid, Matrix4d.CreateTranslation(10, 0, 0));
    mid.InsertChild(leaf, Matrix4d.Scale(2));
    Vector3d w = Vector3d.TransformPosition(new Vector3d(1, 0, 0), leaf.ToWorld());
    Assert.Equal(new Vector3d(12, 0, 0), w);
  }

  [Fact]
  public void Textures_apply_outermost_first()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var leaf = new IntervalSolid(0, 1);
    root.InsertChild(leaf, Matrix4d.Identity);
    var outer = new CheckerTexture(1, 1, new double[] { 1, 1, 1 });
    var inner = new CheckerTexture(2, 2, new double[] { 0, 0, 0 });
    root.SetAttribute(PropertyName.TEXTURE, outer);
    leaf.SetAttribute(PropertyName.TEXTURE, inner);
    LinkedList<ITexture> list = leaf.GetTextures()!;
    Assert.Equal(new ITexture[] { outer, inner }, list);
  }

  [Fact]
  public void Complete_resolves_material_colour_and_default_model()
  {
    var root = new CSGInnerNode(SetOperation.Union);
    var leaf = new IntervalSolid(0, 1);
    root.InsertChild(leaf, Matrix4d.Identity);
    var mat = new PhongMaterial(new double[] { 0.1, 0.2, 0.3 }, 0.1, 0.5, 0.4, 8);
    root.SetAttribute(PropertyName.MATERIAL, mat);
    Vector3d p1 = Vector3d.UnitX;
    Intersection i = Intersection.FirstIntersection(root.Intersect(new Vector3d(-5, 0, 0), p1), ref p1)!;
    i.Complete();
    Assert.IsType<PhongModel>(i.ReflectanceModel);
    Assert.Same(mat, i.Material);
    Assert.Equal(mat.Color, i.SurfaceColor);
    Assert.NotSame(mat.Color, i.SurfaceColor);    // a copy: textures may change it
    Assert.Equal(new Vector3d(0, 0, 0), i.CoordWorld);
  }

  [Fact]
  public void FirstIntersection_skips_hits_behind_and_within_epsilon()
  {
    var leaf = new IntervalSolid(0, 1);
    Vector3d p1 = Vector3d.UnitX;
    Intersection? i = Intersection.FirstIntersection(leaf.Intersect(new Vector3d(0.0, 0, 0), p1), ref p1);
    Assert.NotNull(i);
    Assert.Equal(1.0, i!.T);   // the hit at t = 0 is the origin itself
  }

  [Fact]
  public void FirstRealIntersection_ignores_no_shadow_solids()
  {
    var leaf = new IntervalSolid(1, 2);
    leaf.SetAttribute(PropertyName.NO_SHADOW, true);
    Vector3d p1 = Vector3d.UnitX;
    LinkedList<Intersection>? list = leaf.Intersect(Vector3d.Zero, p1);
    Assert.NotNull(Intersection.FirstIntersection(list, ref p1));
    Assert.Null(Intersection.FirstRealIntersection(list, ref p1));
  }
}
