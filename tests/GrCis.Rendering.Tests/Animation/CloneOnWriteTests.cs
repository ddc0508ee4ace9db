using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.Animation;

public class CloneOnWriteTests
{
  const string Offset = "offset";

  /// <summary>
  /// root (animated, still) ├─ still sphere at x = −5
  ///                        └─ mover (translation "offset": x = t) ─ inner (static CSG) ─ sphere
  /// </summary>
  static (AnimatedRayScene scene, AnimatedCSGInnerNode root, TestSphere still, AnimatedNodeTransform mover, CSGInnerNode inner, TestSphere moving) Scene()
  {
    var animator = new PropertyAnimator { Start = 0.0, End = 10.0 };
    // Open knots on a straight line: Catmull–Rom reproduces x = t exactly.
    animator.newProperty(Offset, 0.0, 10.0, 10.0, PropertyAnimator.InterpolationStyle.Once,
      new List<Vector3d> { new(-10, 0, 0), new(0, 0, 0), new(10, 0, 0), new(20, 0, 0) });

    var root = new AnimatedCSGInnerNode(SetOperation.Union);
    var still = new TestSphere();
    root.InsertChild(still, Matrix4d.CreateTranslation(-5.0, 0.0, 0.0));
    var mover = new AnimatedNodeTransform(Offset, null, Matrix4d.Identity);
    root.InsertChild(mover, Matrix4d.Identity);
    var inner = new CSGInnerNode(SetOperation.Union);
    mover.InsertChild(inner, Matrix4d.Identity);
    var moving = new TestSphere();
    inner.InsertChild(moving, Matrix4d.CreateScale(0.5));

    var scene = new AnimatedRayScene { Start = 0.0, End = 10.0, Animator = animator, Intersectable = root };
    scene.Time = 0.0;
    return (scene, root, still, mover, inner, moving);
  }

  static T? Find<T>(ISceneNode node) where T : class =>
    node as T ?? node.Children.Select(Find<T>).FirstOrDefault(x => x != null);

  [Fact]
  public void Setting_time_moves_the_node_from_the_animator()
  {
    (AnimatedRayScene scene, _, _, AnimatedNodeTransform mover, _, TestSphere moving) = Scene();
    scene.Time = 4.0;
    Assert.Equal(4.0, mover.Translation.X, 12);
    Assert.Equal(4.0, moving.ToWorld().Row3.X, 12);
  }

  [Fact]
  public void Static_subtrees_of_a_still_node_are_shared_and_animated_nodes_are_distinct()
  {
    (AnimatedRayScene scene, AnimatedCSGInnerNode root, TestSphere still, AnimatedNodeTransform mover, CSGInnerNode inner, TestSphere moving) = Scene();

    var clone = (AnimatedRayScene)scene.Clone();
    var root2 = (AnimatedCSGInnerNode)clone.Intersectable!;
    var mover2 = root2.Children.OfType<AnimatedNodeTransform>().Single();

    Assert.NotSame(root, root2);
    Assert.Same(still, root2.Children.First());
    Assert.Same(root, still.Parent);
    Assert.NotSame(mover, mover2);
    Assert.Same(root2, mover2.Parent);
    Assert.Same(mover, root.Children.Last());
  }

  [Fact]
  public void Static_nodes_below_a_moving_node_are_relinked_to_the_clone_sharing_their_data()
  {
    (AnimatedRayScene scene, _, _, AnimatedNodeTransform mover, CSGInnerNode inner, TestSphere moving) = Scene();
    moving.SetAttribute(PropertyName.COLOR, new double[] { 1, 0, 0 });

    var clone = (AnimatedRayScene)scene.Clone();
    var mover2 = Find<AnimatedNodeTransform>((ISceneNode)clone.Intersectable!)!;
    var inner2 = (CSGInnerNode)mover2.Children.Single();
    var moving2 = (TestSphere)inner2.Children.Single();

    Assert.NotSame(inner, inner2);
    Assert.Same(mover2, inner2.Parent);
    Assert.Same(inner2, moving2.Parent);
    Assert.Same(moving.GetLocalAttribute(PropertyName.COLOR), moving2.GetLocalAttribute(PropertyName.COLOR));
    // The original tree is untouched.
    Assert.Same(mover, inner.Parent);
    Assert.Same(inner, moving.Parent);
  }

  [Fact]
  public void Two_clones_at_different_times_used_concurrently_each_see_their_own_time()
  {
    (AnimatedRayScene scene, _, _, _, _, _) = Scene();
    const int rounds = 2000;
    var failures = new List<string>();
    var barrier = new Barrier(2);

    void Worker(double t0)
    {
      var mine = (AnimatedRayScene)SceneCloner.CloneForWorker(scene);
      MT.scene = mine;
      try
      {
        for (int k = 0; k < rounds; k++)
        {
          double t = t0 + (k % 10) * 0.1;
          barrier.SignalAndWait();
          mine.Time = t;
          barrier.SignalAndWait();
          // A ray along +z through the moving sphere's centre hits it at world x = t.
          Vector3d p0 = new(t, 0.0, -10.0), p1 = Vector3d.UnitZ;
          Intersection? hit = Intersection.FirstIntersection(mine.Intersectable!.Intersect(p0, p1), ref p1);
          hit?.Complete();
          if (hit == null || System.Math.Abs(hit.CoordWorld.X - t) > 1e-9 || System.Math.Abs(hit.CoordWorld.Z + 0.5) > 1e-9 ||
              System.Math.Abs(hit.Normal.Z + 1.0) > 1e-9 || System.Math.Abs(mine.Animator!.Time - t) > 0.0)
            lock (failures)
              failures.Add($"t={t}: hit at {hit?.CoordWorld}, normal {hit?.Normal}");
        }
      }
      finally
      {
        MT.scene = null;
      }
    }

    var a = new Thread(() => Worker(1.0));
    var b = new Thread(() => Worker(6.0));
    a.Start();
    b.Start();
    a.Join();
    b.Join();

    Assert.Empty(failures);
    Assert.Equal(0.0, scene.Time);
  }
}
