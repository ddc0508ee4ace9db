//////////////////////////////////////////////////
// Spiral: a parameterised scene - balls on a helix, with a tooltip describing every
// parameter. The parameters are read strictly (GrCis.Scripting.ScriptParameters), so
// `--param "count=abc"` is reported instead of silently ignored. The script also asks
// for its own image size and supersampling (the command line may override them).

Debug.Assert(scene != null);
Debug.Assert(context != null);

context[PropertyName.CTX_TOOLTIP] =
  "count=<int> (balls, default 24), turns=<double> (default 2.5), radius=<double> (default 1.5), " +
  "mat={plastic|mirror|glass} (default plastic), n=<double> (glass IOR, default 1.5)";
context[PropertyName.CTX_WIDTH] = 480;
context[PropertyName.CTX_HEIGHT] = 360;
context[PropertyName.CTX_SUPERSAMPLING] = 4;

GrCis.Scripting.ScriptParameters p = new GrCis.Scripting.ScriptParameters(param);
int count = p.GetInt("count", 24);
double turns = p.GetDouble("turns", 2.5);
double radius = p.GetDouble("radius", 1.5);
string mat = p.GetChoice("mat", "plastic", "plastic", "mirror", "glass");
double n = p.GetDouble("n", 1.5);
if (count < 1)
  throw new ArgumentException($"count must be at least 1, got {count}");

// CSG scene.
CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.7, 0.3, 32));
scene.Intersectable = root;

// Background color.
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };

// Camera.
scene.Camera = new StaticCamera(new Vector3d(0.0, 1.5, -7.0),
                                new Vector3d(0.0, -0.2, 1.0),
                                50.0);

// Light sources.
scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2));

// --- NODE DEFINITIONS ----------------------------------------------------

PhongMaterial pm = null;
if (mat == "mirror")
  pm = new PhongMaterial(new double[] { 1.0, 1.0, 0.8 }, 0.0, 0.1, 0.9, 128);
else if (mat == "glass")
{
  pm = new PhongMaterial(new double[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128);
  pm.n = n;
  pm.Kt = 0.9;
}

// Balls on a helix rising from the floor; colours run through the hues.
for (int i = 0; i < count; i++)
{
  double f = count > 1 ? (double)i / (count - 1) : 0.0;
  double a = 2.0 * Math.PI * turns * f;
  Sphere s = new Sphere();
  s.SetAttribute(PropertyName.COLOR, new double[] { 0.5 + 0.5 * Math.Cos(a), 0.5 + 0.5 * Math.Cos(a + 2.1), 0.5 + 0.5 * Math.Cos(a + 4.2) });
  if (pm != null)
    s.SetAttribute(PropertyName.MATERIAL, pm);
  root.InsertChild(s, Matrix4d.Scale(0.25) * Matrix4d.CreateTranslation(radius * Math.Cos(a), -0.75 + 3.0 * f, radius * Math.Sin(a) + 1.0));
}

// Infinite plane with checker.
Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.3, 0.0, 0.0 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.6, 0.6, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));
