using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Accel;

namespace GrCis.Rendering.Tests.Accel;

/// <summary>
/// A prepared scene records what it decided per member once (<see cref="SceneCapabilities"/>): which kernel answers it,
/// whether it may live in the BVH, how its hits are completed and whether the library's Phong path shades them.
/// </summary>
public class SceneCapabilitiesTests
{
  /// <summary>A student's sphere with its own intersection (same records, but the library cannot know that).</summary>
  sealed class StudentSphere : Sphere
  {
    public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1) => base.Intersect(p0, p1);
  }

  /// <summary>A script's Phong material with its own copy: the hit's material is no longer the library's.</summary>
  sealed class TracedMaterial : PhongMaterial
  {
    public int Copies;

    public override object Clone()
    {
      Copies++;
      return base.Clone();
    }
  }

  sealed class Scene
  {
    public readonly CSGInnerNode Root = new(SetOperation.Union);
    public readonly Sphere Plain = new();
    public readonly StudentSphere Student = new();
    public readonly CSGInnerNode Lens = new(SetOperation.Difference);
    public readonly Sphere LensOuter = new(), LensInner = new();
    public readonly Sphere Custom = new();
    public readonly Plane Floor = new();
    public readonly Cube Box = new();
    public readonly AnimatedCSGInnerNode Moving = new(SetOperation.Union);

    public Scene()
    {
      Root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
      Root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.3, 16));
      Root.InsertChild(Plain, Matrix4d.CreateTranslation(-3.0, 0.0, 0.0));
      Root.InsertChild(Student, Matrix4d.CreateTranslation(3.0, 0.0, 0.0));
      Lens.InsertChild(LensOuter, Matrix4d.Identity);
      Lens.InsertChild(LensInner, Matrix4d.CreateTranslation(0.0, 0.0, -0.5));
      Root.InsertChild(Lens, Matrix4d.CreateTranslation(0.0, 3.0, 0.0));
      Custom.SetAttribute(PropertyName.MATERIAL, new TracedMaterial());
      Root.InsertChild(Custom, Matrix4d.CreateTranslation(0.0, -3.0, 0.0));
      Floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(1.0, 1.0, new[] { 0.0, 0.0, 0.0 }));
      Root.InsertChild(Floor, Matrix4d.CreateTranslation(0.0, 0.0, -2.0));
      Root.InsertChild(Box, Matrix4d.CreateTranslation(6.0, 0.0, 0.0));
      Moving.InsertChild(new Sphere(), Matrix4d.Identity);
      Root.InsertChild(Moving, Matrix4d.CreateTranslation(-6.0, 0.0, 0.0));
    }
  }

  static MemberCapability Of(SceneCapabilities caps, IIntersectable node) =>
    caps.Of(node) ?? throw new Xunit.Sdk.XunitException($"{node.GetType().Name} is not a member of the prepared scene");

  [Fact]
  public void Library_solids_take_their_record_kernel_and_the_surface_completion_of_their_shape()
  {
    var s = new Scene();
    SceneCapabilities caps = PreparedScene.Prepare(s.Root).Capabilities;
    Assert.True(caps.Union);
    MemberCapability plain = Of(caps, s.Plain);
    Assert.Equal((MemberKernel.Record, true, HitCompletion.Sphere, true), (plain.Kernel, plain.Closed, plain.Completion, plain.LibraryPhong));
    Assert.Empty(plain.Leaves);
    MemberCapability floor = Of(caps, s.Floor);
    Assert.Equal((MemberKernel.Record, false, HitCompletion.Plane, true), (floor.Kernel, floor.Closed, floor.Completion, floor.LibraryPhong));
    MemberCapability box = Of(caps, s.Box);
    Assert.Equal((MemberKernel.Record, true, HitCompletion.Cube, true), (box.Kernel, box.Closed, box.Completion, box.LibraryPhong));
  }

  [Fact]
  public void A_students_subclass_overriding_Intersect_is_answered_through_its_list()
  {
    var s = new Scene();
    MemberCapability student = Of(PreparedScene.Prepare(s.Root).Capabilities, s.Student);
    Assert.Equal(MemberKernel.List, student.Kernel);
    Assert.False(student.Closed);   // its records may lie anywhere: tested for every ray
    Assert.False(student.LibraryPhong);   // looked up per hit
    Assert.Equal(HitCompletion.Full, student.Completion);
  }

  [Fact]
  public void A_library_csg_node_takes_the_csg_kernel_and_its_leaves_keep_their_shortcuts_but_an_animated_one_does_not()
  {
    var s = new Scene();
    SceneCapabilities caps = PreparedScene.Prepare(s.Root).Capabilities;
    MemberCapability lens = Of(caps, s.Lens);
    Assert.Equal(MemberKernel.Csg, lens.Kernel);
    Assert.True(lens.Closed);
    Assert.Equal(new IIntersectable[] { s.LensOuter, s.LensInner }, System.Linq.Enumerable.Select(lens.Leaves, l => l.Node));
    Assert.All(lens.Leaves, l => Assert.Equal((MemberKernel.Record, HitCompletion.Sphere, true), (l.Kernel, l.Completion, l.LibraryPhong)));
    Assert.Equal(lens.Leaves[1], Of(caps, s.LensInner));

    // An AnimatedCSGInnerNode changes with time (ITimeDependent): neither flattened nor compiled.
    Assert.Equal(MemberKernel.List, Of(caps, s.Moving).Kernel);
  }

  [Fact]
  public void A_custom_material_keeps_the_kernel_but_not_the_library_phong_path()
  {
    var s = new Scene();
    MemberCapability custom = Of(PreparedScene.Prepare(s.Root).Capabilities, s.Custom);
    Assert.Equal(MemberKernel.Record, custom.Kernel);
    Assert.False(custom.LibraryPhong);
    Assert.Equal(HitCompletion.Full, custom.Completion);
  }

  [Fact]
  public void The_counts_sum_the_decisions_and_the_prepared_scene_reports_them()
  {
    var s = new Scene();
    PreparedScene ps = PreparedScene.Prepare(s.Root);
    SceneCapabilities caps = ps.Capabilities;
    Assert.Equal(7, caps.Members.Count);
    Assert.Equal((4, 1, 2), (caps.RecordKernelCount, caps.CsgKernelCount, caps.ListCount));
    Assert.Equal(4, caps.BoundedCount);   // plain, lens, custom, box
    Assert.Equal(5, caps.LibraryPhongCount);   // plain, the two lens leaves, floor, box
    Assert.Equal(5, caps.SurfaceCompletionCount);
    Assert.Equal((caps.ListCount, caps.CsgKernelCount, caps.BoundedCount), (ps.ListMemberCount, ps.CsgMemberCount, ps.BoundedCount));
    Assert.Null(caps.Of(new Sphere()));
  }

  [Fact]
  public void A_single_solid_scene_is_one_member_without_union_semantics()
  {
    var ball = new Sphere();
    ball.SetAttribute(PropertyName.MATERIAL, new PhongMaterial());
    SceneCapabilities caps = PreparedScene.Prepare(ball).Capabilities;
    Assert.False(caps.Union);
    Assert.Equal(MemberKernel.Record, Assert.Single(caps.Members).Kernel);
  }
}
