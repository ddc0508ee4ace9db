//////////////////////////////////////////////////
// Optics: glass in several shapes in front of a checkered wall - a biconvex lens
// (intersection of two spheres), a glass cube, a hollow glass ball and a mirror.
// Parameters: n = index of refraction of the glass, kt = transparency.

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "n=<double> (index of refraction, default 1.5), kt=<double> (transparency 0-1, default 0.9)";

// Params dictionary.
Dictionary<string, string> p = Util.ParseKeyValueList(param);

// n = <index-of-refraction>
double n = 1.5;
Util.TryParse(p, "n", ref n);

// kt = <transparency>
double kt = 0.9;
Util.TryParse(p, "kt", ref kt);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 64));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.02, 0.02, 0.05 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.0, -6.0),
                                new Vector3d(0.0, -0.15, 1.0),
                                55.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.7));
scene.Sources.Add(new PointLightSource(new Vector3d(-4.0, 5.0, -4.0), 1.1));
scene.Sources.Add(new PointLightSource(new Vector3d(4.0, 3.0, -5.0), 0.5));

// --- NODE DEFINITIONS ----------------------------------------------------

// Biconvex lens: two big spheres intersected, thin along z.
CSGInnerNode lens = new CSGInnerNode(SetOperation.Intersection);
lens.SetAttribute(PropertyName.MATERIAL, Glass(new double[] { 0.05, 0.1, 0.15 }));
lens.InsertChild(new Sphere(), Matrix4d.Scale(2.5) * Matrix4d.CreateTranslation(0.0, 0.0, 2.2));
lens.InsertChild(new Sphere(), Matrix4d.Scale(2.5) * Matrix4d.CreateTranslation(0.0, 0.0, -2.2));
root.InsertChild(lens, Matrix4d.CreateTranslation(-1.9, 0.4, 0.0));

// Glass cube, turned.
Cube c = new Cube();
c.SetAttribute(PropertyName.MATERIAL, Glass(new double[] { 0.1, 0.15, 0.05 }));
root.InsertChild(c, Matrix4d.CreateTranslation(-0.5, -0.5, -0.5) * Matrix4d.Scale(1.2) * Matrix4d.RotateY(0.6) * Matrix4d.RotateX(0.3) * Matrix4d.CreateTranslation(0.3, -0.2, 0.5));

// Hollow glass ball: a sphere minus a smaller one.
CSGInnerNode hollow = new CSGInnerNode(SetOperation.Difference);
hollow.SetAttribute(PropertyName.MATERIAL, Glass(new double[] { 0.15, 0.05, 0.1 }));
hollow.InsertChild(new Sphere(), Matrix4d.Identity);
hollow.InsertChild(new Sphere(), Matrix4d.Scale(0.85));
root.InsertChild(hollow, Matrix4d.Scale(0.8) * Matrix4d.CreateTranslation(2.0, -0.2, 0.2));

// Mirror ball at the back.
Sphere mirror = new Sphere();
mirror.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 1.0, 0.9 }, 0.01, 0.05, 0.95, 512));
root.InsertChild(mirror, Matrix4d.Scale(0.6) * Matrix4d.CreateTranslation(0.8, -0.4, 3.0));

// Checkered floor and wall (seen through the glass).
Plane floor = new Plane();
floor.SetAttribute(PropertyName.COLOR, new double[] { 0.1, 0.1, 0.4 });
floor.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.5, 0.5, new double[] { 0.9, 0.9, 0.9 }));
root.InsertChild(floor, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

Plane wall = new Plane();
wall.SetAttribute(PropertyName.COLOR, new double[] { 0.35, 0.05, 0.0 });
wall.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.7, 0.7, new double[] { 0.7, 0.6, 0.4 }));
root.InsertChild(wall, Matrix4d.RotateY(Math.PI) * Matrix4d.CreateTranslation(0.0, 0.0, 8.0));

PhongMaterial Glass(double[] tint)
{
  PhongMaterial pm = new PhongMaterial(tint, 0.05, 0.05, 0.1, 128);
  pm.n = n;
  pm.Kt = kt;
  return pm;
}
