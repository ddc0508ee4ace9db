// A glow: custom shading through a RecursionFunction lambda.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
scene.Intersectable = root;

DefaultSceneNode glow = new DefaultSceneNode();
double strength = 0.25;

RecursionFunction del = (Intersection i, Vector3d dir, double importance, out RayRecursion rr) =>
{
  double direct = strength * Math.Abs(Vector3d.Dot(i.Normal, dir));
  rr = new RayRecursion(
    new double[] { direct, direct, direct },
    new RayRecursion.RayContribution(i, dir, importance));
  return 144L;
};

glow.SetAttribute(PropertyName.RECURSION, del);
glow.SetAttribute(PropertyName.NO_SHADOW, true);
root.InsertChild(glow, Matrix4d.Identity);
