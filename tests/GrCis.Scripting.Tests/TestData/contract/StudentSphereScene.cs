//////////////////////////////////////////////////
// A student's scene of 2020: two balls on a floor, made of the student's own
// sphere (declared below) or of the library's, "solid=student|library".

Dictionary<string, string> p = Util.ParseKeyValueList(param);
string solid = "student";
Util.TryParse(p, "solid", ref solid);

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.5, 0.5, 0.5 }, 0.1, 0.6, 0.4, 24));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };
scene.Camera = new StaticCamera(new Vector3d(0.4, 0.8, -6.0), new Vector3d(0.0, -0.1, 1.0), 45.0);
scene.Sources = new LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.6));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -4.0), 1.2));

ISolid Ball() => solid == "library" ? new Sphere() : new MySphere();

ISolid s = Ball();
s.SetAttribute(PropertyName.COLOR, new double[] { 1.0, 0.6, 0.1 });
root.InsertChild(s, Matrix4d.Scale(1.6, 0.7, 1.1) * Matrix4d.RotateZ(0.5) * Matrix4d.CreateTranslation(0.3, 0.2, 0.5));
s = Ball();
s.SetAttribute(PropertyName.COLOR, new double[] { 0.2, 0.5, 1.0 });
root.InsertChild(s, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(-1.8, -0.4, -0.8));

Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.7, 0.7, 0.7 });
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.2, 0.0));

/// <summary>Unit sphere; only the local normal is filled, GrCis completes the rest.</summary>
public class MySphere : DefaultSceneNode, ISolid
{
  public override LinkedList<Intersection> Intersect(Vector3d p0, Vector3d p1)
  {
    double OD; Vector3d.Dot(ref p0, ref p1, out OD);
    double DD; Vector3d.Dot(ref p1, ref p1, out DD);
    double OO; Vector3d.Dot(ref p0, ref p0, out OO);
    double d = OD * OD + DD * (1.0 - OO);
    if (d <= 0.0)
      return null;

    d = Math.Sqrt(d);
    LinkedList<Intersection> result = new LinkedList<Intersection>();
    double t = (-OD - d) / DD;
    result.AddLast(new Intersection(this) { T = t, Enter = true, Front = true, CoordLocal = p0 + t * p1 });
    t = (-OD + d) / DD;
    result.AddLast(new Intersection(this) { T = t, Enter = false, Front = false, CoordLocal = p0 + t * p1 });
    return result;
  }

  public override void CompleteIntersection(Intersection inter)
  {
    inter.NormalLocal = inter.CoordLocal;
  }

  public void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = new Vector3d(-1.0, -1.0, -1.0);
    corner2 = new Vector3d(1.0, 1.0, 1.0);
  }
}
