using System.Collections.Generic;
using System.Linq;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Rendering.Tests.SceneGraph;

public class CSGInnerNodeTests
{
  static (double T, bool Enter)[] Hits(CSGInnerNode node, double x0 = -10)
  {
    LinkedList<Intersection>? list = node.Intersect(new Vector3d(x0, 0, 0), Vector3d.UnitX);
    return list == null ? System.Array.Empty<(double, bool)>() : list.Select(i => (i.T, i.Enter)).ToArray();
  }

  static CSGInnerNode Node(SetOperation op, params (double a, double b)[] slabs)
  {
    var n = new CSGInnerNode(op);
    foreach ((double a, double b) in slabs)
      n.InsertChild(new IntervalSolid(a, b), Matrix4d.Identity);
    return n;
  }

  [Fact]
  public void Union_of_overlapping_slabs_has_outer_boundaries_only()
  {
    Assert.Equal(new[] { (10.0, true), (13.0, false) }, Hits(Node(SetOperation.Union, (0, 2), (1, 3))));
  }

  [Fact]
  public void Intersection_keeps_the_common_part()
  {
    Assert.Equal(new[] { (11.0, true), (12.0, false) }, Hits(Node(SetOperation.Intersection, (0, 2), (1, 3))));
  }

  [Fact]
  public void Intersection_of_disjoint_slabs_is_empty()
  {
    Assert.Empty(Hits(Node(SetOperation.Intersection, (0, 1), (2, 3))));
  }

  [Fact]
  public void Difference_turns_the_subtracted_exit_into_an_entry()
  {
    // [0,3] minus [1,2] = [0,1] ∪ [2,3]
    Assert.Equal(new[] { (10.0, true), (11.0, false), (12.0, true), (13.0, false) },
      Hits(Node(SetOperation.Difference, (0, 3), (1, 2))));
  }

  [Fact]
  public void Difference_subtracts_every_later_child()
  {
    // [0,6] − [1,2] − [4,5]
    Assert.Equal(6, Hits(Node(SetOperation.Difference, (0, 6), (1, 2), (4, 5))).Length);
  }

  [Fact]
  public void Xor_keeps_parts_covered_an_odd_number_of_times()
  {
    // [0,2] xor [1,3] = [0,1] ∪ [2,3]
    Assert.Equal(new[] { (10.0, true), (11.0, false), (12.0, true), (13.0, false) },
      Hits(Node(SetOperation.Xor, (0, 2), (1, 3))));
  }

  [Fact]
  public void Ray_starting_inside_sees_only_the_exit_after_origin()
  {
    (double T, bool Enter)[] hits = Hits(Node(SetOperation.Union, (0, 2), (1, 3)), x0: 1.5);
    Assert.Contains((1.5, false), hits);
  }

  [Fact]
  public void Child_transform_is_applied_to_the_ray()
  {
    var n = new CSGInnerNode(SetOperation.Union);
    n.InsertChild(new IntervalSolid(0, 1), Matrix4d.Scale(2, 1, 1) * Matrix4d.CreateTranslation(5, 0, 0));
    Assert.Equal(new[] { (15.0, true), (17.0, false) }, Hits(n));
  }

  [Fact]
  public void Normal_of_a_subtracted_surface_faces_the_ray_after_completion()
  {
    CSGInnerNode n = Node(SetOperation.Difference, (0, 3), (1, 2));
    Vector3d p1 = Vector3d.UnitX;
    LinkedList<Intersection> list = n.Intersect(new Vector3d(-10, 0, 0), p1)!;
    Intersection third = list.ElementAt(2);   // entering again at x = 2 (exit of the hole)
    third.Complete();
    Assert.True(Vector3d.Dot(third.Normal, p1) < 0, $"normal {third.Normal} should face the incoming ray");
  }
}
