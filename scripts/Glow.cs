//////////////////////////////////////////////////
// Glow: luminous halos made of SphereFront shells whose RecursionFunction adds light
// that fades from the centre to the silhouette and lets the ray continue (RayRecursion).
// Parameters: strength = brightness of the halos, falloff = how fast they fade.

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] = "strength=<double> (default 1.0), falloff=<double> (default 3.0)";

Dictionary<string, string> p = Util.ParseKeyValueList(param);
double strength = 1.0;
Util.TryParse(p, "strength", ref strength);
double falloff = 3.0;
Util.TryParse(p, "falloff", ref falloff);

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 0.6, 0.6, 0.7 }, 0.1, 0.6, 0.4, 64));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.0, 0.0, 0.02 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 0.8, -7.0),
                                new Vector3d(0.0, -0.1, 1.0),
                                50.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.4));
scene.Sources.Add(new PointLightSource(new Vector3d(-3.0, 5.0, -4.0), 0.8));

// --- NODE DEFINITIONS ----------------------------------------------------

// Solid things for the halos to shine in front of.
Sphere s = new Sphere();
root.InsertChild(s, Matrix4d.Scale(0.8) * Matrix4d.CreateTranslation(0.0, -0.2, 2.0));

Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.1, 0.1, 0.15 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.5, 0.5, new double[] { 0.3, 0.3, 0.35 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

// Three halos of different colours.
root.InsertChild(Halo(new double[] { 1.0, 0.5, 0.1 }), Matrix4d.Scale(1.0) * Matrix4d.CreateTranslation(-2.2, 0.6, 0.5));
root.InsertChild(Halo(new double[] { 0.2, 0.6, 1.0 }), Matrix4d.Scale(1.3) * Matrix4d.CreateTranslation(0.3, 1.3, 0.0));
root.InsertChild(Halo(new double[] { 0.4, 1.0, 0.3 }), Matrix4d.Scale(0.8) * Matrix4d.CreateTranslation(2.2, 0.2, -0.5));

// A glowing shell: only its front face counts; it casts no shadow.
ISceneNode Halo(double[] color)
{
  SphereFront shell = new SphereFront();
  RecursionFunction glow = (Intersection i, Vector3d dir, double importance, out RayRecursion rr) =>
  {
    // TextureCoord.X of SphereFront = distance from the centre as seen along the ray (0 .. 1).
    double d = Math.Max(0.0, 1.0 - i.TextureCoord.X);
    double k = strength * Math.Pow(d, falloff);
    rr = new RayRecursion(
      new double[] { k * color[0], k * color[1], k * color[2] },
      new RayRecursion.RayContribution(i, dir, importance));
    return 144L + (long)(d * 8.0);
  };
  shell.SetAttribute(PropertyName.RECURSION, glow);
  shell.SetAttribute(PropertyName.NO_SHADOW, true);
  return shell;
}
