//////////////////////////////////////////////////
// Sphere flake on a checkered plane: Scenes.flake, parameters, preprocessing.

if (Util.TryParseBool(context, PropertyName.CTX_PREPROCESSING))
{
  // Nothing to simulate; remember that the stage ran.
  context["flakePreprocessed"] = true;
  return;
}

context[PropertyName.CTX_TOOLTIP] = "depth=<int>, coef=<double>, n=<double>, mat={mirror|glass}";
context[PropertyName.CTX_WIDTH] = 640;
context[PropertyName.CTX_HEIGHT] = 480;

Dictionary<string, string> p = Util.ParseKeyValueList(param);
int depth = 5;
Util.TryParse(p, "depth", ref depth);
double coef = 0.4;
Util.TryParse(p, "coef", ref coef);
double n = 1.6;
Util.TryParse(p, "n", ref n);
string mat = "";
Util.TryParse(p, "mat", ref mat);

CSGInnerNode root = new CSGInnerNode(SetOperation.Union);
root.SetAttribute(PropertyName.REFLECTANCE_MODEL, new PhongModel());
root.SetAttribute(PropertyName.MATERIAL, new PhongMaterial(new double[] { 1.0, 0.8, 0.1 }, 0.1, 0.6, 0.4, 128));
scene.Intersectable = root;
scene.BackgroundColor = new double[] { 0.0, 0.05, 0.07 };
scene.Background = new DefaultBackground(scene.BackgroundColor);

scene.Camera = new StaticCamera(new Vector3d(1.6, 2.2, -7.0), new Vector3d(-0.12, -0.3, 1.0), 50.0);

scene.Sources = new System.Collections.Generic.LinkedList<ILightSource>();
scene.Sources.Add(new AmbientLightSource(0.8));
scene.Sources.Add(new PointLightSource(new Vector3d(-5.0, 4.0, -3.0), 1.2));

PhongMaterial pm = new PhongMaterial(new double[] { 1.0, 0.6, 0.1 }, 0.1, 0.85, 0.05, 16);
if (mat == "mirror")
  pm = new PhongMaterial(new double[] { 1.0, 1.0, 0.8 }, 0.0, 0.1, 0.9, 128);
else if (mat == "glass")
{
  pm = new PhongMaterial(new double[] { 0.0, 0.2, 0.1 }, 0.05, 0.05, 0.1, 128);
  pm.n = n;
  pm.Kt = 0.9;
}

ISceneNode flake = Scenes.flake(depth, coef);
flake.SetAttribute(PropertyName.MATERIAL, pm);
root.InsertChild(flake, Matrix4d.Identity);

Plane pl = new Plane();
pl.SetAttribute(PropertyName.COLOR, new double[] { 0.3, 0.0, 0.0 });
pl.SetAttribute(PropertyName.TEXTURE, new CheckerTexture(0.6, 0.6, new double[] { 1.0, 1.0, 1.0 }));
root.InsertChild(pl, Matrix4d.RotateX(-MathHelper.PiOver2) * Matrix4d.CreateTranslation(0.0, -1.0, 0.0));

context[PropertyName.CTX_ALGORITHM] = new RayTracing();
